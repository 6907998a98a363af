// The steps of [Muraki] Sec. 4 one by one, with values derived from the geometry:
// G1 judgement (Sec. 4.1, Fig. 8 a), the local frame and reference planes (Fig. 8 b),
// tangent planes from the corners, the cross-boundary lines stopping before they
// re-enter a concave region (Sec. 4.3), and the boundary curves through averaged
// corners (Sec. 4.1, Fig. 9).
#include <gtest/gtest.h>

#include <cmath>

#include "fit/boundary_curves.h"
#include "fit/boundary_samples.h"
#include "fit/corner_normals.h"
#include "fit/edge_faces.h"
#include "fit/judge_g1.h"
#include "fit/local_frame.h"
#include "fit/outside_samples.h"
#include "fit_models.h"

namespace trimkit::fit {
namespace {

// Two planar faces meeting at a 90° crease along x = 0: not G1.
geom::Model crease() {
    geom::Model m;
    geom::Face floor;
    floor.surface = geom::plane_patch({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0, 2, 0, 1);
    floor.loops = {test::polygon_loop({{0, 0}, {2, 0}, {2, 1}, {0, 1}}, true)};
    test::add_face(m, floor);
    geom::Face wall;
    wall.surface = geom::plane_patch({0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 0, 2, 0, 1);  // (z, y)
    wall.loops = {test::polygon_loop({{0, 0}, {0, 1}, {2, 1}, {2, 0}}, true)};
    wall.loops[0].coedges[0].edge = m.faces[0].loops[0].coedges[3].edge;  // (0,1)->(0,0) of the floor, reversed
    wall.loops[0].coedges[0].edge_reversed = true;
    test::add_face(m, wall);
    return m;
}

TEST(JudgeG1, SmoothJoinsAreG1AndCreasesAreNot) {
    const geom::Model strip = test::g1_strip();
    const EdgeFaces uses = edge_faces(strip);
    EXPECT_EQ(judge_g1(strip, uses, 0)[0], (std::vector<bool>{false, true, false, false}));
    const geom::Model c = crease();
    const EdgeFaces cu = edge_faces(c);
    ASSERT_EQ(neighbour_face(c, cu, 0, 0, 3), 1);
    EXPECT_EQ(judge_g1(c, cu, 0)[0], (std::vector<bool>{false, false, false, false}));
}

TEST(LocalFrame, ReferencePlanesOfATiltedRectangle) {
    // The plate's outer loop z = x/10 + 2, 10 x 6: e1 along its long side (1, 0, 0.1)/|.|, n its
    // normal (-0.1, 0, 1)/|.| (the outer loop runs counter-clockwise about it), and
    // the reference rectangle is the plate's own (10.05 x 6) plus 10 % of 10.05. No
    // holes: the boundary is symmetric about the plate's axes, so they are its principal axes.
    geom::Model m = test::plate_with_holes();
    m.faces[0].loops.resize(1);
    const std::vector<BoundarySample> s = boundary_samples(m.faces[0], m.edges, 24);
    const LocalFrame f = local_frame(s, 0);
    const Eigen::Vector3d e1 = Eigen::Vector3d(1, 0, 0.1).normalized(), n = Eigen::Vector3d(-0.1, 0, 1).normalized();
    EXPECT_NEAR(std::abs(f.e1.dot(e1)), 1.0, 1e-9);
    EXPECT_NEAR(f.n.dot(n), 1.0, 1e-9);
    const double length = std::sqrt(101.0), margin = 0.1 * length;
    EXPECT_NEAR(f.x1 - f.x0, length + 2 * margin, 1e-6);
    EXPECT_NEAR(f.y1 - f.y0, 6.0 + 2 * margin, 1e-6);
}

TEST(CornerNormals, ExactOnAQuarterCylinder) {
    // A quarter cylinder's four corners give the radial normals at both arcs' ends;
    // interpolated by length and made normal to each tangent they are radial everywhere.
    geom::Face f;
    f.surface = geom::cylinder_patch({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, 2.0, 0, M_PI / 2, 0, 3);
    f.loops = {geom::natural_boundary_loop(f.surface)};
    geom::Model m;
    test::add_face(m, f);
    const std::vector<BoundarySample> s = boundary_samples(m.faces[0], m.edges, 16);
    const auto normals = corner_normals(s, Eigen::Vector3d(1, 1, 0).normalized());
    double worst = 0;
    for (std::size_t k = 0; k < s.size(); ++k) {
        ASSERT_TRUE(normals[k].has_value()) << k;
        Eigen::Vector3d n = *normals[k] - normals[k]->dot(s[k].tangent) * s[k].tangent;
        const Eigen::Vector3d radial = Eigen::Vector3d(s[k].x.x(), s[k].x.y(), 0).normalized();
        worst = std::max(worst, 1 - n.normalized().dot(radial));
    }
    EXPECT_LT(worst, 1e-5);
}

TEST(OutsideSamples, LinesStopBeforeReenteringAConcaveRegion) {
    // The L-shaped face: lines leaving the notch's edges inward would cross the other
    // arm; every outside sample must lie outside the region (its projection).
    const geom::Model m = test::concave_face();
    const std::vector<BoundarySample> s = boundary_samples(m.faces[0], m.edges, 24);
    const LocalFrame f = local_frame(s, 0);
    std::vector<Eigen::Vector3d> normals;
    std::vector<std::vector<Eigen::Vector2d>> loop(1);
    const auto from_corners = corner_normals(s, f.n);
    for (std::size_t k = 0; k < s.size(); ++k) {
        Eigen::Vector3d n = from_corners[k].value_or(f.n);
        normals.push_back((n - n.dot(s[k].tangent) * s[k].tangent).normalized());
        loop[0].push_back(f.plane(s[k].x));
    }
    const LoopPolygons region(loop);
    const OutsideSamples out = outside_samples(s, normals, f, region);
    ASSERT_GT(out.points.size(), s.size());
    for (const SurfaceSample& p : out.points) EXPECT_FALSE(region.contains(f.plane(p.x)));
    // The concave corner's lines run into the notch and stop: fewer reach the planes.
    std::size_t reached = 0;
    for (const auto& side : out.sides) reached += side.size();
    EXPECT_LT(reached, s.size());
}

TEST(BoundaryCurves, CornersAreSharedByAdjacentCurves) {
    const geom::Model m = test::plate_with_holes();
    const std::vector<BoundarySample> s = boundary_samples(m.faces[0], m.edges, 24);
    const LocalFrame f = local_frame(s, 0);
    std::vector<Eigen::Vector3d> normals(s.size(), f.n);
    const OutsideSamples out = outside_samples(s, normals, f, LoopPolygons({}));
    FitRule rule;
    rule.count_u = rule.count_v = 6;
    const BoundaryCurves c = boundary_curves(out, rule);
    for (int k = 0; k < 4; ++k) ASSERT_TRUE(c.sides[k].has_value()) << k;
    // Corner (0,0): the start of side 0 (u = 0) and of side 2 (v = 0).
    EXPECT_EQ(c.sides[0]->points().front(), c.sides[2]->points().front());
    EXPECT_EQ(c.sides[1]->points().back(), c.sides[3]->points().back());
    // A plane's cross-boundary lines stay in it: the curves lie in the plate's plane.
    const Eigen::Vector3d n = Eigen::Vector3d(-0.1, 0, 1).normalized();
    for (int k = 0; k < 4; ++k)
        for (const auto& p : c.sides[k]->points()) EXPECT_NEAR(n.dot(p - Eigen::Vector3d(0, 0, 2)), 0.0, 1e-9);
}

}  // namespace
}  // namespace trimkit::fit
