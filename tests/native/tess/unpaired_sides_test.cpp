#include "tess/unpaired_sides.h"

#include <gtest/gtest.h>

#include "mesh/mesh.h"
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

// A lone face: a strip 10 long and 0.12 wide meshed as a zigzag between its sides
// y = 0 (A, B) and y = 0.12 (C, D). D lies within 0.2 of the open side A B and
// projects between its ends, but beyond the triangle's side B C, which the strip's
// next triangle shares: across the face's own interior, not across a crack. Split
// there, (D, B, C) would fold back (bug25837_S.igs at 0.01 of its diagonal: 23
// backward triangles, area 1.018x). No split; the mesh stays as it was.
TEST(UnpairedSides, VertexAcrossAStripThinnerThanTheDistanceIsNoTJunction) {
    mesh::Mesh m;
    m.positions = {{0, 0, 0}, {10, 0, 0}, {3, 0.12, 0}, {7, 0.12, 0}, {10, 0.12, 0}, {0, 0.12, 0}};
    m.triangles = {{0, 1, 2}, {1, 4, 3}, {1, 3, 2}, {0, 2, 5}};
    m.face_ids = {0, 0, 0, 0};
    ASSERT_NEAR(mesh::surface_area(m), 1.2, 1e-12);
    EXPECT_EQ(close_t_junctions(m, 0.2), 0u);
    EXPECT_EQ(m.triangle_count(), 4u);
    EXPECT_NEAR(mesh::surface_area(m), 1.2, 1e-12);
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


// An n x n grid of unit squares on z = 0 cut into four faces by quadrant, each face
// with its own vertices (as a model mesh has them), its triangles appended in two runs
// out of face order (close_t_junctions appends split triangles at the end), and one
// sliver against a chord between two faces. Derived: the open sides are the grid's 4n
// outer sides and the sliver's one unpaired use of the chord.
TEST(UnpairedSides, FacesPairedApartGiveTheSameSidesOnAnyThreads) {
    const int n = 40, half = n / 2;
    mesh::Mesh m;
    std::vector<std::pair<std::array<std::int32_t, 3>, std::int32_t>> late;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const std::int32_t face = (i >= half) * 2 + (j >= half);
            const auto v = [&](int x, int y) {
                m.positions.emplace_back(x, y, 0);
                return static_cast<std::int32_t>(m.positions.size() - 1);
            };
            const std::int32_t a = v(i, j), b = v(i + 1, j), c = v(i + 1, j + 1), d = v(i, j + 1);
            const std::array<std::int32_t, 3> first{a, b, c}, second{a, c, d};
            m.triangles.push_back(first);
            m.face_ids.push_back(face);
            if (face == 1 && j % 2 == 0) {
                late.emplace_back(second, face);
            } else {
                m.triangles.push_back(second);
                m.face_ids.push_back(face);
            }
        }
    for (const auto& [triangle, face] : late) {
        m.triangles.push_back(triangle);
        m.face_ids.push_back(face);
    }
    // The sliver: face 0's chord from (half, 0) to (half, 1) repeated by a flat
    // triangle through a point just off it.
    const auto at = [&](double x, double y) {
        m.positions.emplace_back(x, y, 0);
        return static_cast<std::int32_t>(m.positions.size() - 1);
    };
    m.triangles.push_back({at(half, 1), at(half, 0), at(half - 1e-3, 0.5)});
    m.face_ids.push_back(0);

    const auto topology = position_triangles(m, position_groups(m));
    const std::vector<TriangleSide> one = unpaired_sides(m, topology, 1);
    const std::vector<TriangleSide> two = unpaired_sides(m, topology, 2);
    // The sliver's three sides: the chord (used three times, once left over) and its
    // two short sides, which nothing else uses.
    EXPECT_EQ(one.size(), static_cast<std::size_t>(4 * n + 3));
    ASSERT_EQ(two.size(), one.size());
    for (std::size_t k = 0; k < one.size(); ++k) {
        EXPECT_EQ(one[k].triangle, two[k].triangle);
        EXPECT_EQ(one[k].corner, two[k].corner);
    }
    EXPECT_EQ(count_position_open_edges(m, 2), one.size());
    EXPECT_EQ(position_groups(m, false, 2), position_groups(m, false, 1));
}

}  // namespace
}  // namespace trimkit::tess
