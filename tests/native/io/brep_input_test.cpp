// io/brep_input.h: the stream OCCT's .brep reader gets. Values past the end of the
// text are " 0" tokens up to kMaxPadding characters, then BrepInputEnded; a failed
// extraction throws; line() and past_end() say where reading stopped.
#include <gtest/gtest.h>

#include <string>

#include "io/brep_input.h"

namespace trimkit::io {
namespace {

TEST(BrepInput, ANumberAtTheVeryEndIsNotPastTheEnd) {
    BrepInput in("Shapes 2\n+1 17");
    std::string word;
    int count = 0, orientation = 0, index = 0;
    in >> word >> count >> orientation >> index;
    EXPECT_EQ(word, "Shapes");
    EXPECT_EQ(count, 2);
    EXPECT_EQ(orientation, 1);
    EXPECT_EQ(index, 17);
    EXPECT_FALSE(in.past_end());
    EXPECT_EQ(in.line(), 2);
}

TEST(BrepInput, ValuesPastTheEndAreZerosUntilThePaddingRunsOut) {
    BrepInput in("7");
    int value = -1;
    in >> value;
    EXPECT_EQ(value, 7);
    in >> value;
    EXPECT_EQ(value, 0);
    EXPECT_TRUE(in.past_end());
    EXPECT_EQ(in.line(), 0);
    // Each " 0" is 2 characters: the padding ends after kMaxPadding / 2 values at most.
    std::size_t read = 1;
    EXPECT_THROW(
        for (; read <= kMaxPadding; ++read) in >> value, BrepInputEnded);
    EXPECT_LE(read, kMaxPadding / 2 + 1);
}

TEST(BrepInput, AWordWhereANumberBelongsThrowsOnItsLine) {
    BrepInput in("1 2\n3 x 4\n");
    int a = 0, b = 0, c = 0, d = 0;
    in >> a >> b >> c;
    EXPECT_EQ(c, 3);
    EXPECT_THROW(in >> d, std::ios_base::failure);
    EXPECT_EQ(in.line(), 2);
    EXPECT_FALSE(in.past_end());
}

}  // namespace
}  // namespace trimkit::io
