#include "tess/unpaired_sides.h"

#include <gtest/gtest.h>

#include "mesh/open_edges.h"
#include "tess/close_t_junctions.h"
#include "tess/snap_boundary_vertices.h"

namespace trimkit::tess {
namespace {

// hammer.iges face 5: a boundary vertex B just off the chord A-C gives face 0 a
// sliver (C, A, B) whose side C->A repeats the side of its own interior triangle
// (C, X, A); face 1's triangle (Y, C, A) runs along the chord. Edge A-C is used
// three times, and face 1's use is the one without a partner.
mesh::Mesh sliver_against_chord() {
    mesh::Mesh m;
    const Eigen::Vector3d A(0, 0, 0), C(2, 0, 0), B(1, -0.01, 0), X(1, 1, 0), Y(1, -1, 0);
    m.positions = {A, C, B, X, Y, A, C};  // 5, 6: face 1's own copies of A and C
    m.triangles = {{1, 0, 2}, {1, 3, 0}, {4, 6, 5}};
    m.face_ids = {0, 0, 1};
    return m;
}

TEST(UnpairedSides, ChordUsedThreeTimesLeavesTheOtherFacesSideOpen) {
    const mesh::Mesh m = sliver_against_chord();
    const auto topology = position_triangles(m, position_groups(m));
    const std::vector<TriangleSide> open = unpaired_sides(m, topology);
    ASSERT_EQ(open.size(), 7u);  // 2 + 2 + 2 outer sides, and face 1's C->A
    int on_chord = 0;
    for (const TriangleSide& s : open)
        if (s.triangle == 2 && s.corner == 1) ++on_chord;
    EXPECT_EQ(on_chord, 1);
    mesh::Mesh positions = m;
    positions.triangles = topology;
    EXPECT_EQ(mesh::count_open_edges(positions), 7u);  // the odd use counts too
    EXPECT_EQ(count_position_open_edges(m), 7u);
}

TEST(UnpairedSides, ClosingTheTJunctionPairsEverySideOfTheChord) {
    mesh::Mesh m = sliver_against_chord();
    EXPECT_EQ(close_t_junctions(m, 0.02), 1u);  // B split into face 1's chord
    EXPECT_EQ(m.triangle_count(), 4u);
    EXPECT_EQ(m.face_ids, (std::vector<std::int32_t>{0, 0, 1, 1}));
    EXPECT_EQ(count_position_open_edges(m), 4u);  // only the outer sides
    // Not closed when B lies farther off the chord than the distance.
    mesh::Mesh far = sliver_against_chord();
    EXPECT_EQ(close_t_junctions(far, 0.005), 0u);
    EXPECT_EQ(count_position_open_edges(far), 7u);
}

TEST(UnpairedSides, FacesOfOppositeOrientationStillPair) {
    // Two loose faces meeting at a line, the second one flipped: the shared edge is
    // used twice in the same direction and is closed.
    mesh::Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}};
    m.triangles = {{0, 1, 2}, {0, 1, 3}};
    m.face_ids = {0, 1};
    EXPECT_EQ(unpaired_sides(m, m.triangles).size(), 4u);
}

}  // namespace
}  // namespace trimkit::tess
