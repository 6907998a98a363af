// geom/clamped_int.h: every double, NaN and infinities included, lands in [lo, hi]
// without passing through an out-of-range conversion.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "geom/clamped_int.h"

namespace trimkit::geom {
namespace {

TEST(ClampedInt, InsideTheRangeTruncates) {
    EXPECT_EQ(clamped_int(3.0, 0, 10), 3);
    EXPECT_EQ(clamped_int(std::floor(3.7), 0, 10), 3);
    EXPECT_EQ(clamped_int(std::ceil(3.2), 0, 10), 4);
    EXPECT_EQ(clamped_int(-2.0, -5, 5), -2);
}

TEST(ClampedInt, OutsideTheRangeAndNotFiniteAreClamped) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(clamped_int(1e17, 0, 10), 10);
    EXPECT_EQ(clamped_int(-1e300, 0, 10), 0);
    EXPECT_EQ(clamped_int(inf, 1, 7), 7);
    EXPECT_EQ(clamped_int(-inf, 1, 7), 1);
    EXPECT_EQ(clamped_int(std::nan(""), 1, 7), 1);
    EXPECT_EQ(clamped_int(10.0, 0, 10), 10);
    EXPECT_EQ(clamped_int(0.0, 0, 10), 0);
}

}  // namespace
}  // namespace trimkit::geom
