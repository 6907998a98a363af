// TriangleBound: the bound of a triangle from its (u,v) box, in one Bezier patch or across several.
#include <gtest/gtest.h>

#include <cmath>

#include "tess/triangle_bound.h"

namespace trimkit::tess {
namespace {

// S(u,v) = (u, v, u^2 + v^2) over [0,1]^2 with `spans` knot spans each way (interior
// knots of multiplicity `multiplicity`): S_uu = S_vv = (0, 0, 2), S_uv = 0, so a
// triangle in a du x dv box is within (2 du^2 + 2 dv^2) / 8 of S.
geom::NurbsSurface paraboloid(int spans, int multiplicity = 1) {
    std::vector<Eigen::Vector3d> P;
    const double a[3] = {0, 0, 1};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) P.emplace_back(0.5 * i, 0.5 * j, a[i] + a[j]);
    geom::NurbsSurface S(2, 2, {0, 0, 0, 1, 1, 1}, {0, 0, 0, 1, 1, 1}, 3, 3, P);
    for (int k = 1; k < spans; ++k)
        for (int m = 0; m < multiplicity; ++m) S = S.insert_knot_u(double(k) / spans).insert_knot_v(double(k) / spans);
    return S;
}

Eigen::AlignedBox2d box(double u0, double v0, double u1, double v1) {
    return Eigen::AlignedBox2d(Eigen::Vector2d(u0, v0), Eigen::Vector2d(u1, v1));
}

double paraboloid_bound(double du, double dv) { return (2.0 * du * du + 2.0 * dv * dv) / 8.0; }

TEST(TriangleBound, AcrossPatchesTheLargestSecondDerivativesOverTheBox) {
    const geom::NurbsSurface S = paraboloid(4);
    TriangleBound bound(S, nullptr, ErrorMode::kGuaranteed, 1.0);
    // Three spans by two: the block bound over the whole box.
    EXPECT_NEAR(bound(box(0.1, 0.3, 0.7, 0.6)), paraboloid_bound(0.6, 0.3), 1e-12);
    // In one span (a box ending on a knot line stays in the span before it): at most the same.
    EXPECT_LE(bound(box(0.25, 0.5, 0.5, 0.75)), paraboloid_bound(0.25, 0.25) + 1e-12);
    EXPECT_GT(bound(box(0.25, 0.5, 0.5, 0.75)), 0.0);
}

TEST(TriangleBound, NoBoundAcrossACreaseNorOutsideTheSurface) {
    const geom::NurbsSurface creased = paraboloid(2, 2);  // C^0 at u = v = 0.5
    TriangleBound bound(creased, nullptr, ErrorMode::kGuaranteed, 1.0);
    EXPECT_TRUE(std::isinf(bound(box(0.4, 0.1, 0.6, 0.2))));
    EXPECT_NEAR(bound(box(0.1, 0.1, 0.4, 0.2)), paraboloid_bound(0.3, 0.1), 1e-12);
    const geom::NurbsSurface smooth = paraboloid(2);
    TriangleBound smooth_bound(smooth, nullptr, ErrorMode::kGuaranteed, 1.0);
    EXPECT_NEAR(smooth_bound(box(0.4, 0.1, 0.6, 0.2)), paraboloid_bound(0.2, 0.1), 1e-12);
    EXPECT_TRUE(std::isinf(smooth_bound(box(0.9, 0.1, 1.1, 0.2))));
}

}  // namespace
}  // namespace trimkit::tess
