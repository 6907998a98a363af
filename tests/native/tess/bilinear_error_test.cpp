#include "tess/bilinear_error.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace trimkit::tess
