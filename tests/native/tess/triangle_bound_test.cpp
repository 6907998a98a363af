// TriangleBound: the bound of a triangle from its (u,v) box, in one Bezier patch or across several.
#include <gtest/gtest.h>

#include <cmath>

#include "tess/triangle_bound.h"
#include "surface_test_support.h"

namespace trimkit::tess {
namespace {

using test::paraboloid;

Eigen::AlignedBox2d box(double u0, double v0, double u1, double v1) {
    return Eigen::AlignedBox2d(Eigen::Vector2d(u0, v0), Eigen::Vector2d(u1, v1));
}

// test::paraboloid's bound for a du x dv box: (2 du^2 + 2 dv^2) / 8.
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
    const geom::NurbsSurface creased = paraboloid(2, false, 2);  // C^0 at u = v = 0.5
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
