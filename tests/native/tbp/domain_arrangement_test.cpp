// Tests for tbp/domain_arrangement.h: faces cover the triangle exactly, cuts
// split it, crossings and islands are handled, dangling cuts are ignored.
#include "tbp/domain_arrangement.h"

#include <gtest/gtest.h>

namespace trimkit::tbp {
namespace {

using Cut = std::array<Eigen::Vector2d, 2>;

double area(const TriangleArrangement& a, const ArrangementFace& f) {
    double s = 0;
    for (const auto& t : f.triangles) {
        const Eigen::Vector2d e = a.points[t[1]] - a.points[t[0]], g = a.points[t[2]] - a.points[t[0]];
        const double ta = 0.5 * (e.x() * g.y() - e.y() * g.x());
        EXPECT_GT(ta, 0);
        s += ta;
    }
    return s;
}

double total(const TriangleArrangement& a) {
    double s = 0;
    for (const auto& f : a.faces) s += area(a, f);
    return s;
}

TEST(ArrangeTriangle, NoCutsIsOneFace) {
    const TriangleArrangement a = arrange_triangle({});
    ASSERT_EQ(a.faces.size(), 1u);
    EXPECT_NEAR(total(a), 0.5, 1e-15);
}

TEST(ArrangeTriangle, SideToSideCutInTwoPieces) {
    // cut from (0.5, 0) on the bottom side to (0, 0.5) on the left: corner (0,0) cut off
    const TriangleArrangement a = arrange_triangle({Cut{Eigen::Vector2d(0.5, 1e-13), Eigen::Vector2d(-1e-13, 0.5)}});
    ASSERT_EQ(a.faces.size(), 2u);
    EXPECT_NEAR(total(a), 0.5, 1e-14);
    const double small = std::min(area(a, a.faces[0]), area(a, a.faces[1]));
    EXPECT_NEAR(small, 0.125, 1e-12);
}

TEST(ArrangeTriangle, CrossingCutsAndPolylines) {
    const TriangleArrangement a = arrange_triangle({Cut{Eigen::Vector2d(0.2, 0), Eigen::Vector2d(0.2, 0.8)},
                                                    Cut{Eigen::Vector2d(0, 0.3), Eigen::Vector2d(0.35, 0.3)},
                                                    Cut{Eigen::Vector2d(0.35, 0.3), Eigen::Vector2d(0.7, 0.3)}});
    EXPECT_EQ(a.faces.size(), 4u);
    EXPECT_NEAR(total(a), 0.5, 1e-14);
}

TEST(ArrangeTriangle, IslandAndDanglingCut) {
    const Eigen::Vector2d p(0.1, 0.1), q(0.3, 0.1), r(0.3, 0.3), s(0.1, 0.3);
    const TriangleArrangement a =
        arrange_triangle({Cut{p, q}, Cut{q, r}, Cut{r, s}, Cut{s, p}, Cut{Eigen::Vector2d(0.6, 0.05), Eigen::Vector2d(0.5, 0.2)}});
    EXPECT_NEAR(total(a), 0.5, 1e-14);
    int square_faces = 0;
    double square_area = 0;
    for (const auto& f : a.faces)
        if (f.sample.x() > 0.1 && f.sample.x() < 0.3 && f.sample.y() > 0.1 && f.sample.y() < 0.3) {
            ++square_faces;
            square_area += area(a, f);
        }
    EXPECT_EQ(square_faces, 1);
    EXPECT_NEAR(square_area, 0.04, 1e-14);
}

// A cut given as two collinear pieces runs straight through their common point: no
// triangle has it as a corner (3 triangles: the corner (0,0) cut off, and the
// quadrilateral (a, (1,0), (0,1), b) left). A third cut
// ending there makes it a junction, a corner of every face around it.
TEST(ArrangeTriangle, StraightThroughVertexIsNoCornerAJunctionIs) {
    const Eigen::Vector2d a(0.6, 0.0), m(0.3, 0.3), b(0.0, 0.6);  // m on the chord from a to b
    const auto uses_m = [&](const TriangleArrangement& arr) {
        int count = 0;
        for (const auto& f : arr.faces)
            for (const auto& t : f.triangles)
                for (int v : t) count += (arr.points[v] - m).norm() < 1e-12;
        return count;
    };
    const TriangleArrangement straight = arrange_triangle({Cut{a, m}, Cut{m, b}});
    ASSERT_EQ(straight.faces.size(), 2u);
    EXPECT_NEAR(total(straight), 0.5, 1e-14);
    EXPECT_EQ(uses_m(straight), 0);
    std::size_t triangles = 0;
    for (const auto& f : straight.faces) triangles += f.triangles.size();
    EXPECT_EQ(triangles, 3u);
    const TriangleArrangement junction = arrange_triangle({Cut{a, m}, Cut{m, b}, Cut{m, Eigen::Vector2d(0.5, 0.5)}});
    ASSERT_EQ(junction.faces.size(), 3u);
    EXPECT_NEAR(total(junction), 0.5, 1e-14);
    EXPECT_GE(uses_m(junction), 3);  // a corner of the triangles on every side
}

}  // namespace
}  // namespace trimkit::tbp
