#include "mesh/open_edges.h"

#include <gtest/gtest.h>

#include "mesh/sample_meshes.h"
#include "mesh/weld_vertices.h"

namespace trimkit::mesh {
namespace {

using Pair = std::array<std::int32_t, 2>;

TEST(OpenEdges, SquareOfTwoTrianglesHasFourBoundaryEdgesCounterClockwise) {
    const Mesh m = test::square_mesh();
    const OpenEdges open = open_edges(m);
    EXPECT_EQ(open.boundary, (std::vector<Pair>{{0, 1}, {3, 0}, {1, 2}, {2, 3}}));
    EXPECT_TRUE(open.non_manifold.empty());
    EXPECT_TRUE(open.misoriented.empty());
    EXPECT_FALSE(open.closed());
    EXPECT_EQ(count_open_edges(m), 4u);
}

TEST(OpenEdges, WeldedCubeIsClosed) {
    Mesh m = test::cube_mesh(1e6);
    weld_vertices(m, {1e-3});
    EXPECT_TRUE(open_edges(m).closed());
}

TEST(OpenEdges, ThreeTrianglesOnOneEdgeAreNonManifold) {
    Mesh m = test::square_mesh();
    m.positions.push_back({0.5, 0.5, 1.0});
    m.triangles.push_back({0, 2, 4});
    m.normals.clear();
    m.uvs.clear();
    m.face_ids.clear();
    const OpenEdges open = open_edges(m);
    ASSERT_EQ(open.non_manifold.size(), 1u);
    EXPECT_EQ(open.non_manifold[0].vertices, (Pair{0, 2}));
    EXPECT_EQ(open.non_manifold[0].count, 3);
    EXPECT_EQ(open.boundary.size(), 6u);
}

TEST(OpenEdges, FlippedTriangleIsMisoriented) {
    Mesh m = test::square_mesh();
    std::swap(m.triangles[1][1], m.triangles[1][2]);  // (0, 3, 2): same direction on 0-2
    const OpenEdges open = open_edges(m);
    EXPECT_EQ(open.misoriented, (std::vector<Pair>{{0, 2}}));
    EXPECT_EQ(open.boundary.size(), 4u);
}

TEST(OpenEdges, DegenerateTriangleContributesItsRealEdge) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}};
    m.triangles = {{0, 1, 1}};
    const OpenEdges open = open_edges(m);
    // 0->1 and 1->0 are one edge used twice in opposite directions: neither open nor misoriented.
    EXPECT_TRUE(open.boundary.empty());
    EXPECT_TRUE(open.misoriented.empty());
}

}  // namespace
}  // namespace trimkit::mesh
