// extrapolated_surface: a B-spline continued past its domain follows its end spans'
// polynomials (a polynomial surface made into B-spline spans by knot insertion) and a
// rational quarter cylinder continues on the same cylinder.
#include "geom/extrapolate_surface.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geom/analytic_surfaces.h"
#include "geom/error.h"

namespace trimkit::geom {
namespace {

// z = u^3 + u v^2 - 2 v over [0, 2] x [0, 1] as one bicubic Bézier patch: control points of
// the graph of a polynomial by the blossom, here obtained by sampling and solving the
// 4 x 4 Bernstein collocation per direction.
NurbsSurface polynomial_patch() {
    auto z = [](double u, double v) { return u * u * u + u * v * v - 2 * v; };
    Eigen::Matrix4d B;
    for (int k = 0; k < 4; ++k)
        for (int j = 0; j < 4; ++j) {
            const double s = k / 3.0;
            const double c[4] = {1, 3, 3, 1};
            B(k, j) = c[j] * std::pow(s, j) * std::pow(1 - s, 3 - j);
        }
    Eigen::Matrix4d Z;
    for (int a = 0; a < 4; ++a)
        for (int b = 0; b < 4; ++b) Z(a, b) = z(2.0 * a / 3, b / 3.0);
    const Eigen::Matrix4d Bi = B.inverse();
    const Eigen::Matrix4d C = Bi * Z * Bi.transpose();
    std::vector<Eigen::Vector3d> P;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) P.emplace_back(2.0 * i / 3, j / 3.0, C(i, j));
    return NurbsSurface(3, 3, {0, 0, 0, 0, 2, 2, 2, 2}, {0, 0, 0, 0, 1, 1, 1, 1}, 4, 4, P);
}

TEST(ExtrapolateSurface, SplinedPolynomialContinuesAsThePolynomial) {
    // Knots at 0.5 and 1.5 in u and 0.25 in v: several spans, the end ones continued.
    const NurbsSurface S = polynomial_patch().insert_knot_u(0.5).insert_knot_u(1.5, 2).insert_knot_v(0.25);
    const NurbsSurface E = extrapolated_surface(S, -0.3, 2.4, -0.2, 1.1);
    EXPECT_DOUBLE_EQ(E.domain_u().first, -0.3);
    EXPECT_DOUBLE_EQ(E.domain_u().second, 2.4);
    EXPECT_DOUBLE_EQ(E.domain_v().first, -0.2);
    EXPECT_DOUBLE_EQ(E.domain_v().second, 1.1);
    for (double u = -0.3; u <= 2.4; u += 0.09)
        for (double v = -0.2; v <= 1.1; v += 0.065) {
            const Eigen::Vector3d p = E.evaluate(u, v);
            EXPECT_NEAR(p.x(), u, 1e-12);
            EXPECT_NEAR(p.y(), v, 1e-12);
            EXPECT_NEAR(p.z(), u * u * u + u * v * v - 2 * v, 1e-11) << u << " " << v;
        }
    // Inside the old domain nothing moved.
    for (double u : {0.0, 0.7, 2.0})
        for (double v : {0.0, 0.4, 1.0}) EXPECT_LT((E.evaluate(u, v) - S.evaluate(u, v)).norm(), 1e-12);
}

TEST(ExtrapolateSurface, RationalQuarterCylinderStaysOnTheCylinder) {
    const double R = 2.0;
    const NurbsSurface S = cylinder_patch({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, R, 0.0, M_PI / 2, 0.0, 1.0);
    const auto [u0, u1] = S.domain_u();
    const NurbsSurface E = extrapolated_surface(S, u0 - 0.1, u1 + 0.1, -0.5, 1.0);
    for (double u = u0 - 0.1; u <= u1 + 0.1; u += 0.02)
        for (double v : {-0.5, 0.0, 0.5, 1.0}) {
            const Eigen::Vector3d p = E.evaluate(u, v);
            EXPECT_NEAR(std::hypot(p.x(), p.y()), R, 1e-12);
            EXPECT_NEAR(p.z(), v, 1e-12);
        }
    // Beyond the quarter: x < 0 past u1, y < 0 before u0.
    EXPECT_LT(E.evaluate(u1 + 0.1, 0).x(), 0.0);
    EXPECT_LT(E.evaluate(u0 - 0.1, 0).y(), 0.0);
}

TEST(ExtrapolateSurface, InsideTheDomainIsTheSameSurfaceAndBadBoundsThrow) {
    const NurbsSurface S = polynomial_patch();
    const NurbsSurface E = extrapolated_surface(S, 0.5, 1.0, 0.2, 0.3);
    EXPECT_EQ(E.points(), S.points());
    EXPECT_THROW(extrapolated_surface(S, -INFINITY, 1.0, 0.0, 1.0), InvalidInput);
}

}  // namespace
}  // namespace trimkit::geom
