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

// A bicubic with uniform unclamped knots 0..7 each way (domain [3, 4]^2), as OCCT's STEP
// round trip gives shell1.brep's faces, widened by 1e-3 at each end: inside its domain
// it is the same surface (before, the last four poles were taken for the end span and
// the patch became the whole control net's, 1.5 - 1.7 off), and just past the domain the
// surface stays next to its edge.
TEST(ExtrapolateSurface, UnclampedKnotsAreClampedToTheDomainFirst) {
    std::vector<Eigen::Vector3d> P;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) P.emplace_back(i + 0.3 * (j % 2), j - 0.2 * (i % 2), (i * j) % 3 - 1.0);
    const std::vector<double> U{0, 1, 2, 3, 4, 5, 6, 7};
    const NurbsSurface S(3, 3, U, U, 4, 4, P);
    ASSERT_DOUBLE_EQ(S.domain_u().first, 3.0);
    const NurbsSurface E = extrapolated_surface(S, 3 - 1e-3, 4 + 1e-3, 3 - 1e-3, 4 + 1e-3);
    for (double u = 3.0; u <= 4.0; u += 0.125)
        for (double v = 3.0; v <= 4.0; v += 0.125) EXPECT_LT((E.evaluate(u, v) - S.evaluate(u, v)).norm(), 1e-12);
    // Past the domain: a small step from the edge moves the point by about the step times
    // the surface's speed there, not to a far pole.
    const NurbsSurface C = S.sub_surface(3, 4, 3, 4);
    EXPECT_LT((E.evaluate(3 - 1e-3, 3.5) - C.evaluate(3, 3.5)).norm(), 1e-2);
    EXPECT_LT((E.evaluate(4 + 1e-3, 4 + 1e-3) - C.evaluate(4, 4)).norm(), 1e-2);
}

TEST(ExtrapolateSurface, InsideTheDomainIsTheSameSurfaceAndBadBoundsThrow) {
    const NurbsSurface S = polynomial_patch();
    const NurbsSurface E = extrapolated_surface(S, 0.5, 1.0, 0.2, 0.3);
    EXPECT_EQ(E.points(), S.points());
    EXPECT_THROW(extrapolated_surface(S, -INFINITY, 1.0, 0.0, 1.0), InvalidInput);
}

}  // namespace
}  // namespace trimkit::geom
