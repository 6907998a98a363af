#include "io/write_stl.h"

#include <gtest/gtest.h>

#include "io/write_test_support.h"
#include "mesh/sample_meshes.h"

namespace trimkit::io {
namespace {

TEST(WriteStl, SizeCountAndFacetsDecode) {
    for (double s : {1e-6, 1.0, 1e6}) {
        const mesh::Mesh m = test::cube_mesh(s);
        const std::string path = test::temp_output(".stl");
        write_stl(path, m);
        const std::string bytes = test::read_bytes(path);
        const std::size_t n = m.triangle_count();
        ASSERT_EQ(bytes.size(), 84 + 50 * n) << "scale " << s;
        EXPECT_NE(bytes.substr(0, 5), "solid");
        EXPECT_EQ(test::le_u32(bytes, 80), n);
        for (std::size_t t = 0; t < n; ++t) {
            const std::size_t at = 84 + 50 * t;
            Eigen::Vector3f facet[4];
            for (int r = 0; r < 4; ++r)
                for (int k = 0; k < 3; ++k) facet[r][k] = test::le_f32(bytes, at + 12 * r + 4 * k);
            // The facet normal is the triangle's and agrees with the cube's outward vertex normal.
            EXPECT_TRUE(facet[0].isApprox(m.normals[m.triangles[t][0]].cast<float>(), 1e-6f))
                << "triangle " << t << " normal " << facet[0].transpose();
            for (int k = 0; k < 3; ++k)
                EXPECT_EQ(facet[1 + k], m.positions[m.triangles[t][k]].cast<float>());
            EXPECT_EQ(test::le_u16(bytes, at + 48), 0u);
        }
    }
}

TEST(WriteStl, DegenerateTriangleGetsZeroNormal) {
    mesh::Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}};
    m.triangles = {{0, 1, 2}};
    const std::string path = test::temp_output(".stl");
    write_stl(path, m);
    const std::string bytes = test::read_bytes(path);
    ASSERT_EQ(bytes.size(), 134u);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(test::le_f32(bytes, 84 + 4 * k), 0.0f);
}

TEST(WriteStl, EmptyMeshIsJustTheHeader) {
    const std::string path = test::temp_output(".stl");
    write_stl(path, mesh::Mesh{});
    const std::string bytes = test::read_bytes(path);
    ASSERT_EQ(bytes.size(), 84u);
    EXPECT_EQ(test::le_u32(bytes, 80), 0u);
}

}  // namespace
}  // namespace trimkit::io
