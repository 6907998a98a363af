#include "mesh/edge_map.h"

#include <gtest/gtest.h>

#include <set>

#include "geom/error.h"

namespace trimkit::mesh {
namespace {

TEST(EdgeMap, TwoTrianglesShareOneEdge) {
    const EdgeMap map = edge_map({{0, 1, 2}, {2, 1, 3}}, 4);
    ASSERT_EQ(map.edges.size(), 5u);
    EXPECT_EQ(map.edges[0], (std::array<std::uint32_t, 2>{0, 1}));
    EXPECT_EQ(map.edges[1], (std::array<std::uint32_t, 2>{1, 2}));
    EXPECT_EQ(map.edges[2], (std::array<std::uint32_t, 2>{0, 2}));
    // Corner 0 of the second triangle runs 2 -> 1: the shared edge.
    EXPECT_EQ(map.corner_edges, (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 4}));
}

TEST(EdgeMap, GridHasEulerEdgeCountAndEveryCornerNamesItsEdge) {
    const int n = 30;  // (n+1)^2 vertices, 2 n^2 triangles
    std::vector<std::array<std::int32_t, 3>> tris;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const int a = i * (n + 1) + j, b = a + 1, c = a + n + 1, d = c + 1;
            tris.push_back({a, b, d});
            tris.push_back({a, d, c});
        }
    const EdgeMap map = edge_map(tris, (n + 1) * (n + 1));
    EXPECT_EQ(map.edges.size(), static_cast<size_t>(2 * n * (n + 1) + n * n));  // V - E + F = 1
    std::set<std::array<std::uint32_t, 2>> unique(map.edges.begin(), map.edges.end());
    EXPECT_EQ(unique.size(), map.edges.size());
    for (size_t c = 0; c < map.corner_edges.size(); ++c) {
        const auto& t = tris[c / 3];
        const std::uint32_t a = t[c % 3], b = t[(c % 3 + 1) % 3];
        EXPECT_EQ(map.edges[map.corner_edges[c]], (std::array<std::uint32_t, 2>{std::min(a, b), std::max(a, b)}));
    }
}

TEST(EdgeMap, IndexOutOfRangeIsRejected) {
    EXPECT_THROW(edge_map({{0, 1, 5}}, 3), geom::InvalidInput);
    EXPECT_THROW(edge_map({{0, -1, 2}}, 3), geom::InvalidInput);
}

}  // namespace
}  // namespace trimkit::mesh
