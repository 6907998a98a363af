#include "mesh/triangulate_polygon.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace trimkit::mesh {
namespace {

double area(const std::vector<Eigen::Vector2d>& uv, const std::array<int, 3>& t) {
    return 0.5 * ((uv[t[1]] - uv[t[0]]).x() * (uv[t[2]] - uv[t[0]]).y() -
                  (uv[t[1]] - uv[t[0]]).y() * (uv[t[2]] - uv[t[0]]).x());
}

double polygon_area(const std::vector<Eigen::Vector2d>& uv, const std::vector<int>& ring) {
    double a = 0;
    for (size_t i = 0; i < ring.size(); ++i) {
        const auto& p = uv[ring[i]];
        const auto& q = uv[ring[(i + 1) % ring.size()]];
        a += p.x() * q.y() - q.x() * p.y();
    }
    return 0.5 * a;
}

// Triangles are CCW (or flat), cover the polygon's area and use every edge of the
// ring exactly once in its direction (so no vertex is skipped: conforming).
void expect_valid(const std::vector<Eigen::Vector2d>& uv, const std::vector<int>& outer,
                  const std::vector<std::vector<int>>& holes,
                  const std::vector<std::array<int, 3>>& tris) {
    double total = 0.0, expected = polygon_area(uv, outer);
    for (const auto& h : holes) expected += polygon_area(uv, h);
    std::map<std::pair<int, int>, int> directed;
    for (const auto& t : tris) {
        EXPECT_GE(area(uv, t), -1e-15);
        total += area(uv, t);
        for (int k = 0; k < 3; ++k) ++directed[{t[k], t[(k + 1) % 3]}];
    }
    EXPECT_NEAR(total, expected, 1e-12 * std::max(1.0, std::abs(expected)));
    auto check_ring = [&](const std::vector<int>& ring) {
        for (size_t i = 0; i < ring.size(); ++i) {
            const std::pair<int, int> e{ring[i], ring[(i + 1) % ring.size()]};
            EXPECT_EQ(directed[e], 1) << "ring edge " << e.first << "->" << e.second;
        }
    };
    check_ring(outer);
    for (const auto& h : holes) check_ring(h);
}

TEST(TriangulatePolygon, ConvexCellWithSidePoints) {
    // A cell with T-junction points on every side: no vertex may be dropped.
    std::vector<Eigen::Vector2d> uv = {{0, 0}, {0.5, 0}, {1, 0}, {1, 0.25}, {1, 0.5}, {1, 1},
                                       {0.3, 1}, {0, 1}, {0, 0.5}};
    std::vector<int> ring = {0, 1, 2, 3, 4, 5, 6, 7, 8};
    EXPECT_TRUE(is_convex(uv, ring));
    const auto tris = triangulate_polygon(uv, ring);
    EXPECT_EQ(tris.size(), ring.size() - 2);
    expect_valid(uv, ring, {}, tris);
}

TEST(TriangulatePolygon, NonConvexWithCollinearAndTouching) {
    // An L-shape with collinear points and a notch whose tip touches another vertex's line.
    std::vector<Eigen::Vector2d> uv = {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 1}};
    std::vector<int> ring = {0, 1, 2, 3, 4, 5, 6, 7};
    EXPECT_FALSE(is_convex(uv, ring));
    const auto tris = triangulate_polygon(uv, ring);
    EXPECT_EQ(tris.size(), ring.size() - 2);
    expect_valid(uv, ring, {}, tris);
}

TEST(TriangulatePolygon, HoleIsBridged) {
    std::vector<Eigen::Vector2d> uv = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    std::vector<int> outer = {0, 1, 2, 3};
    std::vector<int> hole;
    for (int k = 0; k < 12; ++k) {
        const double a = -2 * M_PI * k / 12;
        uv.emplace_back(0.5 + 0.2 * std::cos(a), 0.5 + 0.2 * std::sin(a));
        hole.push_back(4 + k);
    }
    const auto tris = triangulate_polygon(uv, outer, {hole});
    EXPECT_EQ(tris.size(), 4u + 12u);  // n + 2h - 2 for one hole
    expect_valid(uv, outer, {hole}, tris);
}

TEST(TriangulatePolygon, ZeroAreaSliverStaysConnected) {
    // Out and back along one line: only flat triangles, but every edge is used.
    std::vector<Eigen::Vector2d> uv = {{0, 0}, {0.25, 0}, {0.5, 0}, {1, 0}, {0.7, 0}};
    std::vector<int> ring = {0, 1, 2, 3, 4};
    const auto tris = triangulate_polygon(uv, ring);
    EXPECT_EQ(tris.size(), 3u);
    for (const auto& t : tris) EXPECT_NEAR(area(uv, t), 0.0, 1e-15);
}

TEST(TriangulatePolygon, SpiralManyVertices) {
    // A comb: deeply non-convex, 2 * 50 teeth.
    std::vector<Eigen::Vector2d> uv;
    const int teeth = 50;
    for (int k = 0; k < teeth; ++k) {
        uv.emplace_back(k, 0.0);
        uv.emplace_back(k + 0.5, 0.0);
    }
    uv.emplace_back(teeth, 0.0);
    for (int k = teeth; k > 0; --k) {
        uv.emplace_back(k, 1.0);
        uv.emplace_back(k - 0.5, 0.2);
    }
    uv.emplace_back(0.0, 1.0);
    std::vector<int> ring(uv.size());
    for (size_t i = 0; i < ring.size(); ++i) ring[i] = static_cast<int>(i);
    const auto tris = triangulate_polygon(uv, ring);
    EXPECT_EQ(tris.size(), ring.size() - 2);
    expect_valid(uv, ring, {}, tris);
}

TEST(TriangulatePolygon, DuplicatesAndTinyInput) {
    std::vector<Eigen::Vector2d> uv = {{0, 0}, {1, 0}, {0, 1}};
    EXPECT_EQ(triangulate_polygon(uv, {0, 0, 1, 1, 2, 0}).size(), 1u);
    EXPECT_TRUE(triangulate_polygon(uv, {0, 1}).empty());
}

}  // namespace
}  // namespace trimkit::mesh

namespace trimkit::mesh {
namespace {

// as1-oc-214-mat.stp's plate: one cell holding a 180 x 150 rectangle and six round
// holes, two rows of them on one horizontal line each. The second hole's ray met the
// first hole's bridge and took the copy of its end vertex on the wrong side: the
// ring crossed itself and ear clipping folded triangles (mesh area 2.3x).
TEST(TriangulatePolygon, HolesBridgedToOneVertexTakeTheFacingCopy) {
    std::vector<Eigen::Vector2d> uv{{-90, -75}, {90, -75}, {90, 75}, {-90, 75}};
    const std::vector<int> outer{0, 1, 2, 3};
    const double cx[6] = {-42.5, -42.5, 42.5, 42.5, -65, 65}, cy[6] = {12.99, -12.99, -12.99, 12.99, 0, 0};
    const int sides = 24;
    for (int count = 1; count <= 6; ++count) {
        std::vector<std::vector<int>> holes;
        uv.resize(4);
        for (int h = 0; h < count; ++h) {
            std::vector<int> hole;
            for (int k = 0; k < sides; ++k) {  // clockwise, starting at the leftmost point
                const double a = M_PI - 2 * M_PI * k / sides;
                hole.push_back(static_cast<int>(uv.size()));
                uv.emplace_back(cx[h] + 5 * std::cos(a), cy[h] + 5 * std::sin(a));
            }
            holes.push_back(std::move(hole));
        }
        SCOPED_TRACE(std::to_string(count) + " holes");
        expect_valid(uv, outer, holes, triangulate_polygon(uv, outer, holes));
    }
}

}  // namespace
}  // namespace trimkit::mesh
