// fill_sliver_holes closes holes narrower than a width (issue 9: the lobes that
// repair_trim_loop drops from self-crossing loops left 44 open edges on the closed
// solid of bug32596_abc_0_13.step) and leaves wider ones open.
#include <gtest/gtest.h>

#include "mesh/mesh.h"
#include "tess/fill_sliver_holes.h"
#include "tess/snap_boundary_vertices.h"

namespace trimkit::tess {
namespace {

constexpr double kHeight = 1e-3;  // the sliver's height over its base A B

// The unit square A B C D fanned from E = (1/2, kHeight) above its base A B, less
// the sliver A B E (faces 0: A E D, E C D and 1: E B C), on the triangle A F B below
// the base (face 2, F = (1/2, -1)): the sliver is a hole between faces 0, 1 and 2.
mesh::Mesh square_less_sliver() {
    mesh::Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, kHeight, 0}, {0.5, -1, 0}};
    m.triangles = {{0, 4, 3}, {4, 2, 3}, {4, 1, 2}, {0, 5, 1}};
    m.face_ids = {0, 0, 1, 2};
    return m;
}

TEST(FillSliverHoles, ThinHoleIsClosedOrientedLikeItsNeighbours) {
    mesh::Mesh m = square_less_sliver();
    ASSERT_EQ(count_position_open_edges(m), 8u);  // the outer A F B C D and the hole A B E
    // The sliver's width 2 A / P: area kHeight / 2, perimeter 1 + 2 sqrt(1/4 + kHeight²).
    const double perimeter = 1.0 + 2.0 * std::sqrt(0.25 + kHeight * kHeight);
    const double width = kHeight / perimeter;
    EXPECT_EQ(fill_sliver_holes(m, 1.01 * width, 64), 1);
    ASSERT_EQ(m.triangles.size(), 5u);
    EXPECT_EQ(count_position_open_edges(m), 5u);  // the outer boundary only
    // The fan runs A B E counter-clockwise like the rest (normal +z).
    const auto& t = m.triangles.back();
    const Eigen::Vector3d n = (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]);
    EXPECT_GT(n.z(), 0.0);
    EXPECT_NEAR(mesh::surface_area(m), 1.5, 1e-15);
    EXPECT_EQ(m.face_ids.size(), 5u);
}

TEST(FillSliverHoles, HoleWiderThanTheWidthStaysOpen) {
    mesh::Mesh m = square_less_sliver();
    const double perimeter = 1.0 + 2.0 * std::sqrt(0.25 + kHeight * kHeight);
    EXPECT_EQ(fill_sliver_holes(m, 0.99 * kHeight / perimeter, 64), 0);
    EXPECT_EQ(m.triangles.size(), 4u);
    // The outer boundary A F B C D (area 3/2, perimeter 3 + sqrt 5: width 0.57) is
    // not a sliver at a width below that: only the sliver is filled.
    EXPECT_EQ(fill_sliver_holes(m, 0.5, 64), 1);
    EXPECT_EQ(count_position_open_edges(m), 5u);
}

TEST(FillSliverHoles, HoleWhoseNeighbourRunsTheOtherWayIsClosed) {
    // Face 2's triangle flipped (A B F): its side along the hole runs A -> B like the
    // fan would, so no cycle runs every side against its triangle (bug32596 after the
    // trims spent their share: two chains from one vertex to another).
    mesh::Mesh m = square_less_sliver();
    m.triangles[3] = {0, 1, 5};
    ASSERT_EQ(count_position_open_edges(m), 8u);
    const double perimeter = 1.0 + 2.0 * std::sqrt(0.25 + kHeight * kHeight);
    EXPECT_EQ(fill_sliver_holes(m, 1.01 * kHeight / perimeter, 64), 1);
    EXPECT_EQ(count_position_open_edges(m), 5u);
}

}  // namespace
}  // namespace trimkit::tess
