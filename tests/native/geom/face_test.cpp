// Tests for geom/face.h: the natural boundary loop.
#include "geom/face.h"

#include <gtest/gtest.h>

namespace trimkit::geom {
namespace {

TEST(Face, NaturalBoundaryLoopRunsCounterClockwise) {
    std::vector<Eigen::Vector3d> P{{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}};
    const NurbsSurface S(1, 1, {-1, -1, 2, 2}, {3, 3, 7, 7}, 2, 2, P);
    const Loop loop = natural_boundary_loop(S);
    EXPECT_TRUE(loop.outer);
    ASSERT_EQ(loop.coedges.size(), 4u);
    const Eigen::Vector2d expected[4] = {{-1, 3}, {2, 3}, {2, 7}, {-1, 7}};
    double twice_area = 0.0;
    for (int i = 0; i < 4; ++i) {
        const NurbsCurve2d& c = loop.coedges[i].curve;
        EXPECT_EQ(c.degree(), 1);
        EXPECT_EQ(loop.coedges[i].edge, -1);
        const auto [a, b] = c.domain();
        const Eigen::Vector2d start = c.evaluate(a), end = c.evaluate(b);
        EXPECT_EQ(start, expected[i]);
        EXPECT_EQ(end, expected[(i + 1) % 4]);
        // Each coedge ends where the next starts.
        const NurbsCurve2d& next = loop.coedges[(i + 1) % 4].curve;
        EXPECT_EQ(end, next.evaluate(next.domain().first));
        twice_area += start.x() * end.y() - end.x() * start.y();
    }
    EXPECT_DOUBLE_EQ(twice_area, 2.0 * 3.0 * 4.0);  // positive: counter-clockwise
}

}  // namespace
}  // namespace trimkit::geom
