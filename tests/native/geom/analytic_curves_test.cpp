#include "geom/analytic_curves.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "geom/arc_parameter_map.h"
#include "geom/error.h"

namespace trimkit::geom {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Max |f(C(t))| over `n` + 1 uniform samples of the domain.
double max_residual(const NurbsCurve3d& c, const std::function<double(const Eigen::Vector3d&)>& f,
                    int n = 400) {
    const auto [a, b] = c.domain();
    double worst = 0;
    for (int j = 0; j <= n; ++j) worst = std::max(worst, std::abs(f(c.evaluate(a + (b - a) * j / n))));
    return worst;
}

// A rigid motion taking the xy plane to a tilted plane, for 3D conic tests.
Eigen::Affine3d tilt() {
    Eigen::Affine3d T = Eigen::Affine3d::Identity();
    T.rotate(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
    T.pretranslate(Eigen::Vector3d(5, -1, 2));
    return T;
}

TEST(AnalyticCurves, LineSegmentKeepsItsParameterRange) {
    const Eigen::Vector3d P0(1, 2, 3), P1(-2, 0, 7);
    NurbsCurve3d l = line_segment(P0, P1, 2.0, 5.0);
    EXPECT_EQ(l.degree(), 1);
    EXPECT_EQ(l.domain().first, 2.0);
    EXPECT_EQ(l.domain().second, 5.0);
    for (double t : {2.0, 2.5, 4.0, 5.0})
        EXPECT_LT((l.evaluate(t) - (P0 + (t - 2.0) / 3.0 * (P1 - P0))).norm(), 1e-14);
    NurbsCurve2d l2 = line_segment(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1));
    EXPECT_LT((l2.evaluate(0.25) - Eigen::Vector2d(0.25, 0.25)).norm(), 1e-15);
    EXPECT_THROW(line_segment(P0, P1, 1.0, 1.0), InvalidInput);
    EXPECT_THROW(line_segment(P0, Eigen::Vector3d(NAN, 0, 0)), InvalidInput);
}

TEST(AnalyticCurves, CircularArcUsesOnlyThePlaneOfYAxis) {
    // y_axis need not be unit or orthogonal to x_axis.
    NurbsCurve3d arc = circular_arc(Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 0, 0),
                                    Eigen::Vector3d(3, 3, 0), 1.0, 0.0, kPi);
    EXPECT_LT((arc.evaluate(kPi / 2) - Eigen::Vector3d(0, 1, 0)).norm(), 1e-15);
    EXPECT_EQ(arc.degree(), 2);
    EXPECT_TRUE(arc.is_rational());
}

TEST(AnalyticCurves, CircularArcHasUnitSpeedAtKnots) {
    // dt/dθ = α / sin α at the knots, so |C'(t)| = r sin α / α there.
    const double r = 3;
    NurbsCurve3d arc = circular_arc(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(),
                                    Eigen::Vector3d::UnitY(), r, 0.0, 2 * kPi);
    const double alpha = kPi / 4;
    for (double t : {0.0, kPi / 2, kPi, 2 * kPi})
        EXPECT_NEAR(arc.derivatives(t, 1)[1].norm(), r * std::sin(alpha) / alpha, 1e-12);
}

TEST(AnalyticCurves, CircularArcAtLargeAndSmallScale) {
    for (double scale : {1e-6, 1.0, 1e6}) {
        const Eigen::Vector3d c = scale * Eigen::Vector3d(1, 2, 3);
        NurbsCurve3d arc = circular_arc(c, Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(),
                                        scale, -0.2, 4.0);
        EXPECT_LT(max_residual(arc, [&](const Eigen::Vector3d& p) {
                      return (p - c).norm() / scale - 1.0;
                  }), 1e-14);
        EXPECT_LT(max_residual(arc, [&](const Eigen::Vector3d& p) { return (p - c).y() / scale; }),
                  1e-15);
    }
}

TEST(AnalyticCurves, EllipseArcParameterIsTheEccentricAngle) {
    const Eigen::Vector3d c(0, 1, 2), X(0, 0, 1), Y(1, 0, 0);
    const double a = 3, b = 0.5;
    for (auto [t0, t1] : {std::pair{0.0, 2 * kPi}, std::pair{1.0, -2.0}, std::pair{0.1, 0.3}}) {
        NurbsCurve3d e = ellipse_arc(c, X, Y, a, b, t0, t1);
        ArcParameterMap map(t0, t1);
        for (int j = 0; j <= 200; ++j) {
            const double th = t0 + (t1 - t0) * j / 200.0;
            const Eigen::Vector3d expected = c + a * std::cos(th) * X + b * std::sin(th) * Y;
            EXPECT_LT((e.evaluate(map.to_nurbs(th)) - expected).norm(), 1e-12 * a);
        }
    }
}

TEST(AnalyticCurves, ArcsRejectBadInput) {
    const Eigen::Vector3d O = Eigen::Vector3d::Zero(), X = Eigen::Vector3d::UnitX();
    EXPECT_THROW(circular_arc(O, X, Eigen::Vector3d::UnitY(), 0.0, 0, 1), InvalidInput);
    EXPECT_THROW(circular_arc(O, X, Eigen::Vector3d::UnitY(), -1.0, 0, 1), InvalidInput);
    EXPECT_THROW(circular_arc(O, X, 2 * X, 1.0, 0, 1), InvalidInput);
    EXPECT_THROW(circular_arc(O, Eigen::Vector3d::Zero(), X, 1.0, 0, 1), InvalidInput);
    EXPECT_THROW(circular_arc(O, X, Eigen::Vector3d::UnitY(), 1.0, 0, 10), InvalidInput);
    EXPECT_THROW(ellipse_arc(O, X, Eigen::Vector3d::UnitY(), 1.0, 0.0, 0, 1), InvalidInput);
    try {
        circular_arc(O, X, Eigen::Vector3d::UnitY(), -2.0, 0, 1);
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("radius = -2"), std::string::npos) << e.what();
    }
}

TEST(AnalyticCurves, RationalQuadraticArcReproducesAParabola) {
    const Eigen::Affine3d T = tilt();
    auto P = [&](double x) -> Eigen::Vector3d { return T * Eigen::Vector3d(x, x * x, 0); };
    auto D = [&](double x) -> Eigen::Vector3d { return T.linear() * Eigen::Vector3d(1, 2 * x, 0); };
    NurbsCurve3d c = rational_quadratic_arc(P(-1), D(-1), P(2), 3.0 * D(2), P(0.7));
    EXPECT_LT((c.evaluate(0) - P(-1)).norm(), 1e-14);
    EXPECT_LT((c.evaluate(1) - P(2)).norm(), 1e-13);
    for (double w : c.weights()) EXPECT_NEAR(w, 1.0, 1e-12);  // parabola: w = 1
    const Eigen::Affine3d Ti = T.inverse();
    EXPECT_LT(max_residual(c, [&](const Eigen::Vector3d& p) {
                  const Eigen::Vector3d q = Ti * p;
                  return q.y() - q.x() * q.x() + std::abs(q.z());
              }), 1e-12);
}

TEST(AnalyticCurves, RationalQuadraticArcReproducesAHyperbola) {
    // x y = 1 from x = 0.25 to x = 4, through (1, 1), given off the middle.
    auto P = [](double x) { return Eigen::Vector3d(x, 1 / x, 0); };
    auto D = [](double x) { return Eigen::Vector3d(1, -1 / (x * x), 0); };
    NurbsCurve3d c = rational_quadratic_arc(P(0.25), D(0.25), P(4), D(4), P(2.5));
    EXPECT_EQ(c.points().size(), 3u);
    EXPECT_GT(c.weights()[1], 1.0);  // hyperbola: w > 1
    EXPECT_LT(max_residual(c, [](const Eigen::Vector3d& p) { return p.x() * p.y() - 1; }), 1e-12);
}

TEST(AnalyticCurves, RationalQuadraticArcSplitsLargeEllipticArcs) {
    // x²/4 + y² = 1 counter-clockwise from 10° to 340°, through the point at 250°.
    const Eigen::Affine3d T = tilt();
    auto P = [&](double th) -> Eigen::Vector3d {
        return T * Eigen::Vector3d(2 * std::cos(th), std::sin(th), 0);
    };
    auto D = [&](double th) -> Eigen::Vector3d {
        return T.linear() * Eigen::Vector3d(-2 * std::sin(th), std::cos(th), 0);
    };
    const double d = kPi / 180;
    NurbsCurve3d c = rational_quadratic_arc(P(10 * d), D(10 * d), P(340 * d), D(340 * d), P(250 * d));
    EXPECT_EQ(c.points().size(), 9u);  // split twice: four segments below 135° each
    for (double w : c.weights()) EXPECT_GT(w, 0.3);
    const Eigen::Affine3d Ti = T.inverse();
    EXPECT_LT(max_residual(c, [&](const Eigen::Vector3d& p) {
                  const Eigen::Vector3d q = Ti * p;
                  return q.x() * q.x() / 4 + q.y() * q.y() - 1 + std::abs(q.z());
              }), 1e-12);
    // The arc passes through (-2, 0) (it is the long way round).
    double best = 1e9;
    for (int j = 0; j <= 4000; ++j)
        best = std::min(best, ((Ti * c.evaluate(j / 4000.0)) - Eigen::Vector3d(-2, 0, 0)).norm());
    EXPECT_LT(best, 1e-2);
    // A 30° arc stays one segment whatever side the extra point is on.
    NurbsCurve3d small = rational_quadratic_arc(P(0), D(0), P(30 * d), D(30 * d), P(200 * d));
    EXPECT_EQ(small.points().size(), 3u);
    EXPECT_LT((small.evaluate(0.5) - P(15 * d)).norm(), 0.1);
}

TEST(AnalyticCurves, RationalQuadraticArcRejectsDegenerateData) {
    const Eigen::Vector3d O(0, 0, 0), E(2, 0, 0);
    const Eigen::Vector3d T0(1, 1, 0), T2(1, -1, 0);
    EXPECT_NO_THROW(rational_quadratic_arc(O, T0, E, T2, Eigen::Vector3d(1, 0.5, 0)));
    EXPECT_THROW(rational_quadratic_arc(O, T0, E, T2, Eigen::Vector3d(1, 0.5, 0.3)), InvalidInput);
    EXPECT_THROW(rational_quadratic_arc(O, T0, E, T2, Eigen::Vector3d(1, 0, 0)), InvalidInput);
    EXPECT_THROW(rational_quadratic_arc(O, T0, O, T2, Eigen::Vector3d(1, 0.5, 0)), InvalidInput);
    EXPECT_THROW(rational_quadratic_arc(O, Eigen::Vector3d::Zero(), E, T2, Eigen::Vector3d(1, 0.5, 0)),
                 InvalidInput);
    EXPECT_THROW(rational_quadratic_arc(O, E, E, E, Eigen::Vector3d(3, 0, 0)), InvalidInput);
}

TEST(AnalyticCurves, To2dAndTo3dKeepKnotsAndWeights) {
    NurbsCurve3d arc = circular_arc(Eigen::Vector3d(1, 1, 0), Eigen::Vector3d::UnitX(),
                                    Eigen::Vector3d::UnitY(), 2.0, 0.5, 3.0);
    NurbsCurve2d flat = to_2d(arc);
    EXPECT_EQ(flat.knots(), arc.knots());
    EXPECT_EQ(flat.weights(), arc.weights());
    NurbsCurve3d back = to_3d(flat, 4.0);
    for (double t : {0.5, 1.0, 2.2, 3.0}) {
        EXPECT_LT((flat.evaluate(t) - arc.evaluate(t).head<2>()).norm(), 1e-15);
        EXPECT_LT((back.evaluate(t) - arc.evaluate(t) - Eigen::Vector3d(0, 0, 4)).norm(), 1e-14);
    }
}

}  // namespace
}  // namespace trimkit::geom
