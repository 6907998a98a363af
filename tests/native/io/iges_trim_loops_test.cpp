// Regressions of issue 3 in the IGES loop building (UKI60998.igs): trim curves
// projected from model space along a closed surface's seam, and a 143 whose
// first boundary is a hole.
#include <gtest/gtest.h>

#include <cmath>

#include "geom/model.h"
#include "io/read_model.h"
#include "io/trim_loop_repair.h"
#include "test_support.h"

namespace trimkit::io {
namespace {

// Largest gap between consecutive coedges of a loop, in (u,v).
double largest_joint_gap(const geom::Loop& loop) {
    double gap = 0.0;
    for (size_t k = 0; k < loop.coedges.size(); ++k) {
        const geom::NurbsCurve2d& a = loop.coedges[k].curve;
        const geom::NurbsCurve2d& b = loop.coedges[(k + 1) % loop.coedges.size()].curve;
        gap = std::max(gap, (a.evaluate(a.domain().second) - b.evaluate(b.domain().first)).norm());
    }
    return gap;
}

// Faces 1 and 3 are tabulated cylinders bounded by two circles and one seam line
// used twice: the projected seam must be on the low side once and on the high
// side once, so the loop is the whole domain (before: both on one side, the loop
// closed by bridges across the domain, area ~0).
TEST(IgesTrimLoops, UKI60998SeamUsedTwiceBoundsTheWholeCylinder) {
    TRIMKIT_CAD_SAMPLE(path, "iges/UKI60998.igs");
    const geom::Model model = read_model(path);
    ASSERT_EQ(model.faces.size(), 11u);
    for (int f : {1, 3}) {
        const geom::Face& face = model.faces[f];
        ASSERT_EQ(face.loops.size(), 1u) << "face " << f;
        const geom::Loop& loop = face.loops[0];
        EXPECT_EQ(loop.coedges.size(), 4u) << "face " << f << ": no bridges";
        EXPECT_LT(largest_joint_gap(loop), 1e-9) << "face " << f;
        const auto [u0, u1] = face.surface.domain_u();
        const auto [v0, v1] = face.surface.domain_v();
        EXPECT_NEAR(std::abs(signed_area(loop)), (u1 - u0) * (v1 - v0), 1e-6 * (u1 - u0) * (v1 - v0))
            << "face " << f;
    }
}

// Faces 8 and 10 are planes whose 143 lists the circular hole first and the
// rectangle second; the rectangle (larger area) is the outer loop.
TEST(IgesTrimLoops, UKI60998HoleListedFirstIsNotTheOuterLoop) {
    TRIMKIT_CAD_SAMPLE(path, "iges/UKI60998.igs");
    const geom::Model model = read_model(path);
    ASSERT_EQ(model.faces.size(), 11u);
    for (int f : {8, 10}) {
        const geom::Face& face = model.faces[f];
        ASSERT_EQ(face.loops.size(), 2u) << "face " << f;
        EXPECT_TRUE(face.loops[0].outer) << "face " << f << ": outer loop first";
        EXPECT_FALSE(face.loops[1].outer) << "face " << f;
        EXPECT_GT(std::abs(signed_area(face.loops[0])), std::abs(signed_area(face.loops[1])))
            << "face " << f;
        // Outer counter-clockwise, hole clockwise (face.h, not reversed).
        EXPECT_EQ(signed_area(face.loops[0]) > 0, !face.reversed) << "face " << f;
        EXPECT_EQ(signed_area(face.loops[1]) < 0, !face.reversed) << "face " << f;
    }
}

}  // namespace
}  // namespace trimkit::io
