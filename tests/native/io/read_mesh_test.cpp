// Round trips write_X -> read_mesh for the four formats, and hostile input.
#include "io/read_mesh.h"

#include <gtest/gtest.h>

#include <fstream>

#include "geom/error.h"
#include "io/write_glb.h"
#include "io/write_obj.h"
#include "io/write_ply.h"
#include "io/write_stl.h"
#include "write_test_support.h"

namespace trimkit::io {
namespace {

// Two faces of a bent strip with normals, uvs and face ids.
mesh::Mesh sample_mesh() {
    mesh::Mesh m;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 3; ++j) {
            m.positions.emplace_back(0.1 * i + 1e-3 * j, 0.25 * j, 0.01 * i * i);
            m.normals.push_back(Eigen::Vector3d(0.1 * i, 0.0, 1.0).normalized());
            m.uvs.emplace_back(i / 3.0, j / 2.0);
        }
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 2; ++j) {
            const int a = i * 3 + j, b = a + 3, c = a + 1, d = b + 1;
            m.triangles.push_back({a, b, d});
            m.triangles.push_back({a, d, c});
            m.face_ids.push_back(i < 2 ? 0 : 5);
            m.face_ids.push_back(i < 2 ? 0 : 5);
        }
    return m;
}

void expect_same_positions(const mesh::Mesh& a, const mesh::Mesh& b) {
    ASSERT_EQ(a.positions.size(), b.positions.size());
    for (std::size_t i = 0; i < a.positions.size(); ++i)
        EXPECT_LE((a.positions[i] - b.positions[i]).norm(), 1e-7 * (1 + a.positions[i].norm())) << i;
}

TEST(ReadMesh, PlyRoundTrips) {
    const mesh::Mesh m = sample_mesh();
    const std::string path = test::temp_output(".ply");
    write_ply(path, m);
    const mesh::Mesh r = read_mesh(path);
    expect_same_positions(m, r);
    EXPECT_EQ(r.triangles, m.triangles);
    EXPECT_EQ(r.face_ids, m.face_ids);
    ASSERT_EQ(r.uvs.size(), m.uvs.size());
    ASSERT_EQ(r.normals.size(), m.normals.size());
    for (std::size_t i = 0; i < m.uvs.size(); ++i) EXPECT_LE((r.uvs[i] - m.uvs[i]).norm(), 1e-7);
}

TEST(ReadMesh, ObjRoundTripsWithFaceGroups) {
    const mesh::Mesh m = sample_mesh();
    const std::string path = test::temp_output(".obj");
    write_obj(path, m);
    const mesh::Mesh r = read_mesh(path);
    expect_same_positions(m, r);
    EXPECT_EQ(r.triangles, m.triangles);
    EXPECT_EQ(r.face_ids, m.face_ids);
    ASSERT_EQ(r.uvs.size(), m.uvs.size());
    for (std::size_t i = 0; i < m.uvs.size(); ++i) EXPECT_EQ(r.uvs[i], m.uvs[i]);
}

TEST(ReadMesh, StlRoundTripsTriangleCorners) {
    const mesh::Mesh m = sample_mesh();
    const std::string path = test::temp_output(".stl");
    write_stl(path, m);
    const mesh::Mesh r = read_mesh(path);
    ASSERT_EQ(r.triangles.size(), m.triangles.size());
    EXPECT_EQ(r.positions.size(), m.positions.size());  // coincident corners shared
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            EXPECT_LE((r.positions[r.triangles[t][k]] - m.positions[m.triangles[t][k]]).norm(), 1e-7);
}

TEST(ReadMesh, GlbRoundTrips) {
    const mesh::Mesh m = sample_mesh();
    const std::string path = test::temp_output(".glb");
    write_glb(path, m);
    const mesh::Mesh r = read_mesh(path);
    expect_same_positions(m, r);
    EXPECT_EQ(r.triangles, m.triangles);
    ASSERT_EQ(r.uvs.size(), m.uvs.size());
    for (std::size_t i = 0; i < m.uvs.size(); ++i) EXPECT_LE((r.uvs[i] - m.uvs[i]).norm(), 1e-7);
}

TEST(ReadMesh, TruncatedFilesThrowReadError) {
    const mesh::Mesh m = sample_mesh();
    for (const std::string ext : {".ply", ".obj", ".stl", ".glb"}) {
        const std::string path = test::temp_output(ext);
        if (ext == ".ply") write_ply(path, m);
        if (ext == ".obj") write_obj(path, m);
        if (ext == ".stl") write_stl(path, m);
        if (ext == ".glb") write_glb(path, m);
        const std::string bytes = test::read_bytes(path);
        // Cut inside the last face record (for OBJ: the last "f" line keeps one corner).
        const std::size_t cut = ext == ".obj" ? bytes.rfind("f ") + 3 : bytes.size() - 7;
        std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(cut));
        EXPECT_THROW(read_mesh(path), geom::ReadError) << ext;
    }
}

TEST(ReadMesh, GarbageAndLyingCountsThrowReadError) {
    const std::string path = test::temp_output(".ply");
    std::ofstream(path, std::ios::binary) << "ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
                                             "property float x\nproperty float y\nproperty float z\nend_header\n";
    EXPECT_THROW(read_mesh(path), geom::ReadError);
    const std::string obj = test::temp_output(".obj");
    std::ofstream(obj) << "v 0 0 0\nv 1 0 0\nf 1 2 7\n";
    try {
        read_mesh(obj);
        FAIL() << "no ReadError";
    } catch (const geom::ReadError& e) {
        EXPECT_EQ(e.line(), 3);
    }
    const std::string stl = test::temp_output(".stl");
    std::string header(80, ' ');
    header += std::string("\xff\xff\xff\x0f", 4);
    std::ofstream(stl, std::ios::binary) << header;
    EXPECT_THROW(read_mesh(stl), geom::ReadError);
    const std::string glb = test::temp_output(".glb");
    std::ofstream(glb, std::ios::binary) << "glTF garbage garbage";
    EXPECT_THROW(read_mesh(glb), geom::ReadError);
    EXPECT_THROW(read_mesh(test::temp_output(".xyz")), geom::ReadError);
}

}  // namespace
}  // namespace trimkit::io
