// Tests for io/tbp_format.h: round trip, and FILE:LINE errors for hostile input
// (wrong point counts, NaN, degree > 20, malformed or deeply nested JSON).
#include "io/tbp_format.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "geom/error.h"

namespace trimkit::io {
namespace {

tbp::TbpSolid sample_solid() {
    tbp::TbpSolid s;
    s.name = "two \"flat\" triangles";
    s.patches.emplace_back(1, std::vector<Eigen::Vector3d>{{0.1, 0, 0}, {1, 0, 0}, {0, 1, 1e-300}});
    s.patches.emplace_back(1, std::vector<Eigen::Vector3d>{{1, 1, 0}, {0, 1, 0}, {1, 0, -2.5e7}});
    return s;
}

std::string error_of(const std::string& text) {
    try {
        parse_tbp(text, "x.tbp");
    } catch (const geom::ReadError& e) {
        return e.what();
    }
    return "no error";
}

TEST(TbpFormat, RoundTripsExactly) {
    const tbp::TbpSolid s = sample_solid();
    const tbp::TbpSolid r = parse_tbp(tbp_text(s), "mem.tbp");
    EXPECT_EQ(r.name, s.name);
    ASSERT_EQ(r.patches.size(), 2u);
    for (int p = 0; p < 2; ++p)
        for (int q = 0; q < 3; ++q) EXPECT_EQ(r.patches[p].points()[q], s.patches[p].points()[q]);
    const std::string path = (std::filesystem::temp_directory_path() / "trimkit_tbp_format_test.tbp").string();
    write_tbp(s, path);
    EXPECT_EQ(read_tbp(path).patches[1].points()[2], s.patches[1].points()[2]);
    std::filesystem::remove(path);
}

TEST(TbpFormat, ReadsCubicWithUnknownMembers) {
    std::string pts;
    for (int q = 0; q < 10; ++q) pts += std::string(q ? "," : "") + "[" + std::to_string(q) + ",0,1]";
    const tbp::TbpSolid s = parse_tbp("{\"tbp\":1,\"degree\":3,\"extra\":{\"a\":[1]},\"patches\":[[" + pts + "]]}", "c.tbp");
    EXPECT_EQ(s.degree(), 3);
    EXPECT_EQ(s.patches[0].point(0, 0), Eigen::Vector3d(9, 0, 1));  // b003 is last
}

TEST(TbpFormat, WrongPointCountNamesLineAndCounts) {
    const std::string e = error_of("{\"tbp\": 1, \"degree\": 2,\n \"patches\": [\n [[0,0,0],[1,0,0],[0,1,0]]]}");
    EXPECT_NE(e.find("x.tbp:3:"), std::string::npos) << e;
    EXPECT_NE(e.find("patch 0 has 3 control points, expected 6"), std::string::npos) << e;
}

TEST(TbpFormat, RejectsNaNDegreeAndMalformedJson) {
    EXPECT_NE(error_of("{\"tbp\":1,\"degree\":1,\n\"patches\":[[[0,0,0],[NaN,0,0],[0,1,0]]]}").find("x.tbp:2: malformed JSON"), std::string::npos);
    EXPECT_NE(error_of("{\"tbp\":1,\"degree\":1,\"patches\":[[[0,0,0],[1e999,0,0],[0,1,0]]]}").find("malformed JSON"), std::string::npos);
    EXPECT_NE(error_of("{\"tbp\":1,\"degree\":21,\"patches\":[]}").find("degree 21; expected an integer from 1 to 20"), std::string::npos);
    EXPECT_NE(error_of("{\"tbp\":1,\"degree\":2.5,\"patches\":[]}").find("degree 2.5"), std::string::npos);
    EXPECT_NE(error_of("{\"tbp\":2,\"degree\":1,\"patches\":[]}").find("\"tbp\" is not 1"), std::string::npos);
    EXPECT_NE(error_of("{\"tbp\":1,\"degree\":1,\"patches\":[]}").find("empty"), std::string::npos);
    EXPECT_NE(error_of("{\"tbp\":1,\"degree\":1,\"patches\":[[[0,0],[1,0,0],[0,1,0]]]}").find("point 0 is not [x, y, z]"), std::string::npos);
    EXPECT_NE(error_of("{\"tbp\":1,").find("malformed JSON"), std::string::npos);
    EXPECT_NE(error_of("[1]").find("expected a JSON object"), std::string::npos);
    EXPECT_NE(error_of(std::string(100000, '[')).find("nesting deeper"), std::string::npos);
    EXPECT_NE(error_of("").find("x.tbp:1: malformed JSON"), std::string::npos);
}

TEST(TbpFormat, MissingFileIsReadError) {
    EXPECT_THROW(read_tbp("/nonexistent/dir/none.tbp"), geom::ReadError);
}

}  // namespace
}  // namespace trimkit::io
