// ParameterMap: p-curves written in a surface's native (angle, length) parameters
// mapped onto the NurbsSurface built for it, measured on the exact cylinder.
#include "geom/parameter_map.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geom/analytic_curves.h"
#include "geom/analytic_surfaces.h"

namespace trimkit::geom {
namespace {

constexpr double kPi = 3.14159265358979323846;
const double R = 3.0;

// The exact cylinder point at angle θ and height z.
Eigen::Vector3d cylinder_point(double theta, double z) { return {R * std::cos(theta), R * std::sin(theta), z}; }

TEST(ParameterMap, AffineMapMovesControlPointsExactly) {
    ParameterMap m;
    m.v.scale = std::cos(0.3);  // a cone's ruling length to its axial height
    m.u.offset = 2.0;
    const NurbsCurve2d c = to_2d(circular_arc({1, 1, 0}, {1, 0, 0}, {0, 1, 0}, 0.5, 0.0, 2 * kPi));
    const NurbsCurve2d mapped = m.map_curve(c, 1e-9);
    EXPECT_EQ(mapped.points().size(), c.points().size());
    for (double t : {0.0, 0.7, 2.0, 5.5}) EXPECT_TRUE(mapped.evaluate(t).isApprox(m.apply(c.evaluate(t)), 1e-14));
}

TEST(ParameterMap, AxisParallelPolylineKeepsItsTraceExactly) {
    ParameterMap m;
    m.u.arc.emplace(-kPi / 2, kPi / 2);
    const NurbsCurve2d c(1, {0, 0, 1, 2, 2}, {{-kPi / 2, 0.0}, {1.0, 0.0}, {1.0, 4.0}});
    const NurbsCurve2d mapped = m.map_curve(c, 1e-9);
    ASSERT_EQ(mapped.points().size(), 3u);
    const NurbsSurface S = cylinder_patch({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, R, -kPi / 2, kPi / 2, 0, 4);
    // The mapped corners are the exact points at the corners' angles.
    for (int k = 0; k < 3; ++k) {
        const Eigen::Vector2d uv = mapped.points()[k];
        EXPECT_LT((S.evaluate(uv.x(), uv.y()) - cylinder_point(c.points()[k].x(), c.points()[k].y())).norm(), 1e-12);
    }
}

TEST(ParameterMap, CurveAcrossArcKnotsIsRefittedWithinTheTolerance) {
    // A helix-like line θ = 2z over [-π/2, π/2] on a cylinder patch whose arcs have a
    // knot at θ = 0 (two quarter segments): the refit stays on the exact cylinder.
    ParameterMap m;
    m.u.arc.emplace(-kPi / 2, kPi / 2);
    const NurbsSurface S = cylinder_patch({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, R, -kPi / 2, kPi / 2, -1, 1);
    const NurbsCurve2d c = line_segment(Eigen::Vector2d(-kPi / 2, -kPi / 4), Eigen::Vector2d(kPi / 2, kPi / 4));
    const double tol = 1e-8;
    const NurbsCurve2d mapped = m.map_curve(c, tol);
    double worst = 0;
    for (int k = 0; k <= 400; ++k) {
        const double t = static_cast<double>(k) / 400;
        const Eigen::Vector2d st = c.evaluate(t), uv = mapped.evaluate(t);
        worst = std::max(worst, (S.evaluate(uv.x(), uv.y()) - cylinder_point(st.x(), st.y())).norm());
    }
    // |dS/du| <= R (1 + |t - θ| slope): a (u,v) error of tol moves the point by about R·tol.
    EXPECT_LT(worst, 4 * R * tol);
    EXPECT_GT(mapped.points().size(), 4u);
}

TEST(ParameterMap, WoundAxisRepeatsTheArcMapEveryPeriod) {
    AxisMap a;
    a.arc.emplace(0.0, 2 * kPi);
    a.period = 2 * kPi;
    for (double x : {0.3, 1.9, 4.0, 6.0})
        EXPECT_NEAR(a.apply(x + 2 * kPi), a.apply(x) + 2 * kPi, 1e-12) << x;
    EXPECT_NEAR(a.apply(2 * kPi), 2 * kPi, 1e-12);  // knots: parameter = angle
    EXPECT_NEAR(a.apply(3 * kPi), 3 * kPi, 1e-12);
}

}  // namespace
}  // namespace trimkit::geom
