// mesh/grid_cell.h: a point's cell is floor(p / size), and coordinates too far out for
// a 64-bit cell index (or NaN) still give a defined cell.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "mesh/grid_cell.h"

namespace trimkit::mesh {
namespace {

TEST(GridCell, CellIsTheFloorOfPositionOverSize) {
    const GridCell c = GridCell::of(Eigen::Vector3d(2.5, -0.5, 0.0), 1.0);
    EXPECT_EQ(c.x, 2);
    EXPECT_EQ(c.y, -1);
    EXPECT_EQ(c.z, 0);
    EXPECT_TRUE(GridCell::of(Eigen::Vector3d(0.99, 0.0, 0.0), 0.5) == GridCell::of(Eigen::Vector3d(0.51, 0.0, 0.0), 0.5));
}

TEST(GridCell, CoordinatesBeyondTheIndexRangeAreClamped) {
    constexpr double limit = 4.611686018427387904e18;  // 2^62
    const GridCell far = GridCell::of(Eigen::Vector3d(1e300, -1e300, std::nan("")), 1e-9);
    EXPECT_EQ(far.x, static_cast<std::int64_t>(limit));
    EXPECT_EQ(far.y, -static_cast<std::int64_t>(limit));
    EXPECT_EQ(far.z, 0);
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(GridCell::of(Eigen::Vector3d(inf, -inf, 0.0), 1.0).x, static_cast<std::int64_t>(limit));
}

}  // namespace
}  // namespace trimkit::mesh
