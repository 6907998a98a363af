// io/brep_input.h: the stream OCCT's .brep reader gets. Values past the end of the
// text are " 0" tokens up to kMaxPadding characters, then BrepInputEnded; a failed
// extraction throws; line() and past_end() say where reading stopped.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/brep_input.h"

namespace trimkit::io {
namespace {

std::string write_temp(const std::string& name, const std::string& text) {
    const std::string path = (std::filesystem::temp_directory_path() / ("trimkit_brep_input_" + name)).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

TEST(BrepInput, ANumberAtTheVeryEndIsNotPastTheEnd) {
    const std::string path = write_temp("end.txt", "Shapes 2\n+1 17");
    BrepInput in(path);
    std::string word;
    int count = 0, orientation = 0, index = 0;
    in >> word >> count >> orientation >> index;
    EXPECT_EQ(word, "Shapes");
    EXPECT_EQ(count, 2);
    EXPECT_EQ(orientation, 1);
    EXPECT_EQ(index, 17);
    EXPECT_FALSE(in.past_end());
    EXPECT_EQ(in.line(), 2);
    std::filesystem::remove(path);
}

TEST(BrepInput, ValuesPastTheEndAreZerosUntilThePaddingRunsOut) {
    const std::string path = write_temp("padding.txt", "7");
    BrepInput in(path);
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
    std::filesystem::remove(path);
}

TEST(BrepInput, AWordWhereANumberBelongsThrowsOnItsLine) {
    const std::string path = write_temp("word.txt", "1 2\n3 x 4\n");
    BrepInput in(path);
    int a = 0, b = 0, c = 0, d = 0;
    in >> a >> b >> c;
    EXPECT_EQ(c, 3);
    EXPECT_THROW(in >> d, std::ios_base::failure);
    EXPECT_EQ(in.line(), 2);
    EXPECT_FALSE(in.past_end());
    std::filesystem::remove(path);
}

TEST(BrepInput, AMissingFileThrows) {
    EXPECT_THROW(BrepInput("/nonexistent/trimkit/none.brep"), std::runtime_error);
}

}  // namespace
}  // namespace trimkit::io
