#include "tess/bilinear_error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "geom/nurbs_surface.h"
#include "tess/bezier_patch.h"
#include "tess/second_derivative_bound.h"

namespace trimkit::tess {
namespace {

// x = u, y = v, z = u^2 as a Bezier patch of degree (n, 1): the Bernstein coefficients
// of u are i / n, of u^2 i (i - 1) / (n (n - 1)).
BezierPatch parabola_patch(int n) {
    std::vector<Eigen::Vector3d> P;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= 1; ++j) P.emplace_back(double(i) / n, j, double(i) * (i - 1) / (n * (n - 1)));
    std::vector<double> U(n + 1, 0.0);
    U.insert(U.end(), n + 1, 1.0);
    return bezier_patch(geom::NurbsSurface(n, 1, U, {0, 0, 1, 1}, n + 1, 2, P));
}

// S_uu = (0, 0, 2), S_uv = S_vv = 0: the derivatives bound (M_uu + 2 M_uv + M_vv) / 8 =
// 1/4, the exact sagitta of u^2 over [0, 1]. The control net's bound is the spread of
// z_i - i/n = -(i/n)(n - i)/(n - 1), whose largest at i = n/2 is n / (4 (n - 1)): 1/4 + 1/44
// for n = 12, 1/4 + 1/4 for n = 2. A polynomial patch takes the smaller.
TEST(BilinearError, PolynomialPatchTakesTheSmallerOfTheControlNetAndDerivativeBounds) {
    for (int n : {2, 5, 12}) {
        SCOPED_TRACE(n);
        const BezierPatch patch = parabola_patch(n);
        EXPECT_NEAR(second_derivative_bound(patch).error(), 0.25, 1e-12);
        EXPECT_NEAR(bilinear_error(patch, ErrorMode::kGuaranteed, 0.01).bound, 0.25, 1e-12);
    }
}


// Largest |S_ss|, |S_st|, |S_tt| of the patch in its local parameters, sampled on a
// 21 x 21 grid with central differences (h = 1e-4, error O(h^2)).
SecondDerivativeBound sampled_second_derivatives(const BezierPatch& patch) {
    constexpr double h = 1e-4;
    SecondDerivativeBound M;
    for (int a = 0; a <= 20; ++a)
        for (int b = 0; b <= 20; ++b) {
            const double s = std::clamp(a / 20.0, h, 1.0 - h), t = std::clamp(b / 20.0, h, 1.0 - h);
            auto S = [&](double ds, double dt) { return patch.evaluate(s + ds, t + dt); };
            M.M_uu = std::max(M.M_uu, ((S(h, 0) - 2.0 * S(0, 0) + S(-h, 0)) / (h * h)).norm());
            M.M_vv = std::max(M.M_vv, ((S(0, h) - 2.0 * S(0, 0) + S(0, -h)) / (h * h)).norm());
            M.M_uv = std::max(M.M_uv, ((S(h, h) - S(h, -h) - S(-h, h) + S(-h, -h)) / (4 * h * h)).norm());
        }
    return M;
}

// The differences' rounding: about 1e-16 / h^2 = 1e-8 of the coordinates' size.
void expect_bounds(const SecondDerivativeBound& bound, const SecondDerivativeBound& sampled) {
    constexpr double kSlack = 1e-6;
    EXPECT_GE(bound.M_uu, sampled.M_uu * (1 - kSlack) - kSlack);
    EXPECT_GE(bound.M_uv, sampled.M_uv * (1 - kSlack) - kSlack);
    EXPECT_GE(bound.M_vv, sampled.M_vv * (1 - kSlack) - kSlack);
}

// A quarter of a unit cylinder, height 1, as a rational Bezier patch of degree (2, 1)
// (weights 1, 1/sqrt 2, 1 along u): S_ss follows the rational arc, S_tt = S_st = 0 on
// the straight rulings of constant weight.
BezierPatch quarter_cylinder() {
    const double w = std::sqrt(0.5);
    std::vector<Eigen::Vector4d> Pw;
    for (const Eigen::Vector3d& P : {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 1, 0), Eigen::Vector3d(0, 1, 0)})
        for (double z : {0.0, 1.0}) {
            const double wi = P.x() == 1 && P.y() == 1 ? w : 1.0;
            Pw.emplace_back(wi * P.x(), wi * P.y(), wi * z, wi);
        }
    BezierPatch patch;
    patch.p = 2, patch.q = 1, patch.Pw = Pw;
    return patch;
}

// The numerators' Bernstein products (one convolution of binomial-scaled nets): the
// bound holds against sampled derivatives and stays within 4x of them on the quarter
// cylinder (the hull's (w_max / w_min)^2 = 2 times the 2 S_s w_s / w term's share; a
// product without its binomials would be off by up to C(3, 1) C(1, 0) = 3 more).
TEST(SecondDerivativeBound, QuarterCylinderIsBoundedAndTight) {
    const BezierPatch patch = quarter_cylinder();
    const SecondDerivativeBound bound = second_derivative_bound(patch), sampled = sampled_second_derivatives(patch);
    expect_bounds(bound, sampled);
    EXPECT_LE(bound.M_uu, 4.0 * sampled.M_uu);
    EXPECT_NEAR(bound.M_uv, 0.0, 1e-12);
    EXPECT_NEAR(bound.M_vv, 0.0, 1e-12);
    // The chord's sagitta over the quarter, 1 - cos(pi/4), is within the bound's error.
    EXPECT_GE(bound.error(), 1.0 - std::cos(M_PI / 4));
}

// A random rational patch of degree (6, 10), the degrees of linkrods.step's B-splines:
// the bound holds on it, and restricted to a sub-patch (kd_subdivision's inherited
// bound) it holds on the sub-patch in the sub-patch's own parameters.
TEST(SecondDerivativeBound, HighDegreeRationalPatchAndItsSubPatches) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0), weight(0.5, 2.0);
    BezierPatch patch;
    patch.p = 6, patch.q = 10;
    for (int i = 0; i <= 6; ++i)
        for (int j = 0; j <= 10; ++j) {
            const double w = weight(random);
            patch.Pw.emplace_back(w * (i / 6.0 + 0.1 * coordinate(random)), w * (j / 10.0 + 0.1 * coordinate(random)),
                                  w * 0.3 * coordinate(random), w);
        }
    const SecondDerivativeBound M = second_derivative_bound(patch);
    expect_bounds(M, sampled_second_derivatives(patch));
    const BezierPatch left = split_u(patch, 0.3).first;
    expect_bounds(restricted_bound(M, 0.3, 1.0), sampled_second_derivatives(left));
    const BezierPatch top = split_v(left, 0.6).second;
    expect_bounds(restricted_bound(M, 0.3, 0.4), sampled_second_derivatives(top));
    // The sub-patch's own bound, from its own (tighter) hull, holds as well.
    expect_bounds(second_derivative_bound(top), sampled_second_derivatives(top));
}

}  // namespace
}  // namespace trimkit::tess
