#include "geom/curve_interpolation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geom/analytic_curves.h"
#include "geom/arc_parameter_map.h"
#include "geom/error.h"

namespace trimkit::geom {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Max |fit(t) - map(c(t))| over a dense sampling of c's domain.
double max_deviation(const NurbsCurve2d& fit, const NurbsCurve2d& c,
                     const std::function<Eigen::Vector2d(Eigen::Vector2d)>& map) {
    const auto [a, b] = c.domain();
    double worst = 0;
    for (int j = 0; j <= 20000; ++j) {
        const double t = a + (b - a) * j / 20000.0;
        worst = std::max(worst, (fit.evaluate(t) - map(c.evaluate(t))).norm());
    }
    return worst;
}

// The cylinder's native (θ, z) -> NURBS (t, z) map and its C1 lines.
struct CylinderMap {
    ArcParameterMap arc{0.0, 2 * kPi};
    Eigen::Vector2d operator()(const Eigen::Vector2d& q) const {
        return {arc.to_nurbs(q.x()), q.y()};
    }
    MapBreaks breaks() const {
        return {std::vector<double>(arc.angles().begin() + 1, arc.angles().end() - 1), {}};
    }
};

TEST(CurveInterpolation, InterpolatesThePointsAtTheirParameters) {
    std::vector<Eigen::Vector3d> Q;
    for (int k = 0; k <= 12; ++k) Q.emplace_back(k, std::sin(k), std::cos(0.3 * k * k));
    const std::vector<double> u = chord_length_parameters(Q);
    const NurbsCurve3d c = interpolate_curve(Q);
    EXPECT_EQ(c.degree(), 3);
    EXPECT_EQ(c.domain(), std::make_pair(0.0, 1.0));
    for (size_t k = 0; k < Q.size(); ++k) EXPECT_LT((c.evaluate(u[k]) - Q[k]).norm(), 1e-12);
    // Supplied parameters become the curve's; few points lower the degree.
    const std::vector<Eigen::Vector2d> R{{0, 0}, {1, 2}, {3, 1}};
    const NurbsCurve2d q = interpolate_curve(R, 3, {2.0, 2.5, 4.0});
    EXPECT_EQ(q.degree(), 2);
    EXPECT_LT((q.evaluate(2.5) - R[1]).norm(), 1e-14);
}

TEST(CurveInterpolation, ReproducesCubics) {
    std::vector<Eigen::Vector2d> Q;
    std::vector<double> t;
    auto f = [](double x) { return Eigen::Vector2d(x, x * x * x - 2 * x); };
    for (int k = 0; k <= 9; ++k) {
        t.push_back(k / 9.0);
        Q.push_back(f(k / 9.0));
    }
    const NurbsCurve2d c = interpolate_curve(Q, 3, t);
    for (int j = 0; j <= 100; ++j) EXPECT_LT((c.evaluate(j / 100.0) - f(j / 100.0)).norm(), 1e-13);
}

TEST(CurveInterpolation, RejectsBadInput) {
    const std::vector<Eigen::Vector2d> Q{{0, 0}, {1, 1}, {1, 1}, {2, 0}};
    EXPECT_THROW(interpolate_curve(Q), InvalidInput);  // repeated point
    EXPECT_THROW(interpolate_curve(std::vector<Eigen::Vector2d>{{0, 0}}), InvalidInput);
    const std::vector<Eigen::Vector2d> R{{0, 0}, {1, 1}, {2, 0}};
    EXPECT_THROW(interpolate_curve(R, 3, {0.0, 0.0, 1.0}), InvalidInput);
    EXPECT_THROW(interpolate_curve(R, 3, {0.0, 1.0}), InvalidInput);
}

TEST(RefitMappedCurve, StraightLineThroughTheArcMap) {
    const CylinderMap m;
    const NurbsCurve2d line = line_segment(Eigen::Vector2d(0.1, -1), Eigen::Vector2d(6.0, 2));
    const NurbsCurve2d fit = refit_mapped_curve(line, m, 1e-10, m.breaks());
    EXPECT_EQ(fit.domain(), line.domain());
    EXPECT_LT(max_deviation(fit, line, m), 1e-9);
    EXPECT_LT((fit.evaluate(0) - m(Eigen::Vector2d(0.1, -1))).norm(), 1e-15);
    EXPECT_LT((fit.evaluate(1) - m(Eigen::Vector2d(6.0, 2))).norm(), 1e-15);
}

TEST(RefitMappedCurve, CircleThroughTheArcMap) {
    const CylinderMap m;
    // A full circle in (θ, z) around (π, 0.5) crossing θ = π/2 .. 3π/2.
    const NurbsCurve2d circle = to_2d(circular_arc(Eigen::Vector3d(kPi, 0.5, 0), Eigen::Vector3d::UnitX(),
                                                   Eigen::Vector3d::UnitY(), 2.0, 0, 2 * kPi));
    const NurbsCurve2d fit = refit_mapped_curve(circle, m, 1e-10, m.breaks());
    EXPECT_LT(max_deviation(fit, circle, m), 1e-9);
    EXPECT_LT(fit.points().size(), 2000u);
}

TEST(RefitMappedCurve, PolylineKeepsItsCorners) {
    const CylinderMap m;
    std::vector<Eigen::Vector2d> P{{0.2, 0}, {2.0, 1}, {2.5, -1}, {5.0, 0}};
    const NurbsCurve2d poly(1, {0, 0, 1, 2, 3, 3}, P);
    const NurbsCurve2d fit = refit_mapped_curve(poly, m, 1e-10, m.breaks());
    EXPECT_LT(max_deviation(fit, poly, m), 1e-9);
    for (double t : {1.0, 2.0}) EXPECT_LT((fit.evaluate(t) - m(poly.evaluate(t))).norm(), 1e-14);
}

TEST(RefitMappedCurve, FailsCleanly) {
    const NurbsCurve2d line = line_segment(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1));
    auto identity = [](const Eigen::Vector2d& q) { return q; };
    EXPECT_THROW(refit_mapped_curve(line, identity, 0.0), InvalidInput);
    auto nan_map = [](const Eigen::Vector2d& q) { return Eigen::Vector2d(q.x(), NAN); };
    EXPECT_THROW(refit_mapped_curve(line, nan_map, 1e-6), NumericalFailure);
    // Oscillating 10^4 times along the curve: more than kMaxRefitSamples needed.
    auto wavy = [](const Eigen::Vector2d& q) {
        return Eigen::Vector2d(q.x(), std::sin(6.3e4 * q.x()));
    };
    EXPECT_THROW(refit_mapped_curve(line, wavy, 1e-9), NumericalFailure);
    // A kink there converges anyway (refinement concentrates at it), and declared
    // as a break it is exact with the initial samples.
    auto kink = [](const Eigen::Vector2d& q) { return Eigen::Vector2d(q.x(), std::abs(q.x() - 0.4)); };
    EXPECT_LT(max_deviation(refit_mapped_curve(line, kink, 1e-10), line, kink), 1e-9);
    const NurbsCurve2d exact = refit_mapped_curve(line, kink, 1e-12, {{0.4}, {}});
    EXPECT_LT(max_deviation(exact, line, kink), 1e-12);
    EXPECT_LT(exact.points().size(), 20u);
}

}  // namespace
}  // namespace trimkit::geom
