#include "tess/derivative_bounds.h"

#include <gtest/gtest.h>

#include "tess/tess_test_cases.h"

namespace trimkit::tess {
namespace {

// The bounds hold at sampled points (they are sup norms) and are not absurdly loose.
void expect_surface_bounds_hold(const geom::NurbsSurface& S, double max_slack) {
    const SurfaceDerivativeBounds M = surface_derivative_bounds(S);
    const auto [u0, u1] = S.domain_u();
    const auto [v0, v1] = S.domain_v();
    SurfaceDerivativeBounds seen;
    for (int i = 0; i <= 40; ++i)
        for (int j = 0; j <= 40; ++j) {
            const auto d = S.derivatives(u0 + (u1 - u0) * i / 40, v0 + (v1 - v0) * j / 40);
            seen.Mu = std::max(seen.Mu, d.Su.norm());
            seen.Mv = std::max(seen.Mv, d.Sv.norm());
            seen.Muu = std::max(seen.Muu, d.Suu.norm());
            seen.Muv = std::max(seen.Muv, d.Suv.norm());
            seen.Mvv = std::max(seen.Mvv, d.Svv.norm());
        }
    const double eps = 1e-12;
    EXPECT_GE(M.Mu + eps, seen.Mu);
    EXPECT_GE(M.Mv + eps, seen.Mv);
    EXPECT_GE(M.Muu + eps, seen.Muu);
    EXPECT_GE(M.Muv + eps, seen.Muv);
    EXPECT_GE(M.Mvv + eps, seen.Mvv);
    EXPECT_LE(M.Mu, max_slack * seen.Mu);
    EXPECT_LE(M.Mv, max_slack * seen.Mv);
}

TEST(DerivativeBounds, SurfaceBoundsHoldPolynomial) {
    expect_surface_bounds_hold(test::yang_surface(), 3.0);
    expect_surface_bounds_hold(test::skewed_bilinear(), 1.5);
}

TEST(DerivativeBounds, SurfaceBoundsHoldRational) {
    expect_surface_bounds_hold(test::sphere_circle().surface, 6.0);
    expect_surface_bounds_hold(test::cylinder_line().surface, 6.0);
}

TEST(DerivativeBounds, RegionBoundsAreTighter) {
    const geom::NurbsSurface S = test::skewed_bilinear();
    const auto whole = surface_derivative_bounds(S);
    const auto corner = surface_derivative_bounds(
        S, Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(0.1, 0.1)));
    EXPECT_LT(corner.Mu, 0.5 * whole.Mu);
    // A degenerate (iso-line) region is widened, not rejected.
    const auto line = surface_derivative_bounds(
        S, Eigen::AlignedBox2d(Eigen::Vector2d(0.3, 0.2), Eigen::Vector2d(0.3, 0.8)));
    EXPECT_GT(line.Mv, 0.0);
}

TEST(DerivativeBounds, CurveBoundsHold) {
    for (const geom::NurbsCurve2d& c :
         {test::sphere_circle().curve, test::yang_curve(false), test::yang_curve(true)}) {
        const CurveDerivativeBounds M = curve_derivative_bounds(c);
        const auto [a, b] = c.domain();
        for (int k = 0; k <= 200; ++k) {
            const auto d = c.derivatives(a + (b - a) * k / 200, 2);
            EXPECT_GE(M.Mtu + 1e-12, std::abs(d[1].x()));
            EXPECT_GE(M.Mtv + 1e-12, std::abs(d[1].y()));
            EXPECT_GE(M.Mtt + 1e-12, d[2].norm());
        }
    }
    // Polynomial cubic: c'' is linear, so its hodograph bound is exact (3.84 for [Yang] A).
    EXPECT_NEAR(curve_derivative_bounds(test::yang_curve(false)).Mtt, 3.841874, 1e-6);
}

// A degree-2 surface in u with a double knot at u = 0.5 (C^0 there) and a simple
// one at u = 0.25 (C^1); cubic in v without interior knots.
TEST(DerivativeBounds, IsC1InsideSeesC0KnotLines) {
    const std::vector<double> U = {0, 0, 0, 0.25, 0.5, 0.5, 1, 1, 1};
    const std::vector<double> V = {0, 0, 0, 0, 1, 1, 1, 1};
    std::vector<Eigen::Vector3d> P;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 4; ++j) P.emplace_back(i, j, (i % 2) * 0.3);
    const geom::NurbsSurface S(2, 3, U, V, 6, 4, P);
    auto box = [](double u0, double u1) {
        return Eigen::AlignedBox2d(Eigen::Vector2d(u0, 0.2), Eigen::Vector2d(u1, 0.8));
    };
    EXPECT_TRUE(is_c1_inside(S, box(0.1, 0.4)));    // crosses the C^1 knot only
    EXPECT_FALSE(is_c1_inside(S, box(0.4, 0.6)));   // crosses the C^0 knot
    EXPECT_TRUE(is_c1_inside(S, box(0.5, 0.9)));    // ends on it: does not cross
    EXPECT_TRUE(is_c1_inside(S, box(0.6, 0.6)));
}

}  // namespace
}  // namespace trimkit::tess
