#include "io/write_ply.h"

#include <gtest/gtest.h>

#include <limits>
#include <sstream>
#include <vector>

#include "geom/error.h"
#include "io/write_test_support.h"
#include "mesh/sample_meshes.h"

namespace trimkit::io {
namespace {

// Header lines up to and including "end_header", and the offset of the payload.
std::vector<std::string> header_lines(const std::string& bytes, std::size_t& payload) {
    const std::string end = "end_header\n";
    const std::size_t at = bytes.find(end);
    EXPECT_NE(at, std::string::npos) << "no end_header";
    payload = at + end.size();
    std::vector<std::string> lines;
    std::istringstream in(bytes.substr(0, payload));
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

TEST(WritePly, CubeHeaderAndBinaryPayloadDecode) {
    const mesh::Mesh m = test::cube_mesh(2.5, Eigen::Vector3d(-1e3, 0.1, 3.0));
    const std::string path = test::temp_output(".ply");
    write_ply(path, m);
    const std::string bytes = test::read_bytes(path);
    std::size_t at = 0;
    const std::vector<std::string> header = header_lines(bytes, at);
    const std::vector<std::string> expected = {
        "ply", "format binary_little_endian 1.0", "comment written by trimkit",
        "element vertex 24", "property float x", "property float y", "property float z",
        "property float nx", "property float ny", "property float nz", "property float u",
        "property float v", "element face 12", "property list uchar int vertex_indices",
        "property int face_id", "end_header"};
    EXPECT_EQ(header, expected);
    ASSERT_EQ(bytes.size(), at + 24 * 32 + 12 * 17);

    for (std::size_t i = 0; i < m.vertex_count(); ++i) {
        float values[8];
        for (int k = 0; k < 8; ++k) values[k] = test::le_f32(bytes, at + 4 * k);
        at += 32;
        for (int k = 0; k < 3; ++k) {
            EXPECT_EQ(values[k], static_cast<float>(m.positions[i][k])) << "vertex " << i;
            EXPECT_EQ(values[3 + k], static_cast<float>(m.normals[i][k])) << "vertex " << i;
        }
        EXPECT_EQ(values[6], static_cast<float>(m.uvs[i].x()));
        EXPECT_EQ(values[7], static_cast<float>(m.uvs[i].y()));
    }
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
        EXPECT_EQ(static_cast<unsigned char>(bytes[at]), 3u);
        for (int k = 0; k < 3; ++k) EXPECT_EQ(test::le_i32(bytes, at + 1 + 4 * k), m.triangles[t][k]);
        EXPECT_EQ(test::le_i32(bytes, at + 13), m.face_ids[t]);
        at += 17;
    }
}

TEST(WritePly, PositionsOnlyMesh) {
    mesh::Mesh m = test::square_mesh(1e-6);
    m.normals.clear();
    m.uvs.clear();
    m.face_ids.clear();
    const std::string path = test::temp_output(".ply");
    write_ply(path, m);
    const std::string bytes = test::read_bytes(path);
    std::size_t at = 0;
    const std::vector<std::string> header = header_lines(bytes, at);
    EXPECT_EQ(header.size(), 10u);
    EXPECT_EQ(header[header.size() - 2], "property list uchar int vertex_indices");
    ASSERT_EQ(bytes.size(), at + 4 * 12 + 2 * 13);
    EXPECT_EQ(test::le_f32(bytes, at + 12), 1e-6f);  // vertex 1 x
    EXPECT_EQ(test::le_i32(bytes, at + 48 + 13 + 1 + 8), 3);  // triangle 1, third index
}

TEST(WritePly, RejectsValuesBeyondFloatRange) {
    mesh::Mesh m = test::square_mesh();
    m.positions[2].z() = 1e39;
    try {
        write_ply(test::temp_output(".ply"), m);
        ADD_FAILURE() << "write_ply accepted 1e39";
    } catch (const geom::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("write_ply: positions[2] = (1, 1, 1e+39) does not fit a float32"),
                  std::string::npos)
            << e.what();
    }
}

}  // namespace
}  // namespace trimkit::io
