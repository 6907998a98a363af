#include "mesh/mesh.h"

#include <gtest/gtest.h>

#include <limits>

#include "geom/error.h"
#include "mesh/sample_meshes.h"

namespace trimkit::mesh {
namespace {

using geom::InvalidInput;
using test::cube_mesh;
using test::square_mesh;

// Expects validate(m) to throw InvalidInput whose message contains `needle`.
void expect_invalid(const Mesh& m, const std::string& needle) {
    try {
        validate(m);
        ADD_FAILURE() << "validate accepted a mesh; expected an error mentioning " << needle;
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
}

TEST(Mesh, SampleMeshesAreValid) {
    EXPECT_NO_THROW(validate(square_mesh()));
    EXPECT_NO_THROW(validate(cube_mesh()));
    EXPECT_NO_THROW(validate(Mesh{}));
}

TEST(Mesh, ValidateNamesFirstNonFinitePosition) {
    Mesh m = square_mesh();
    m.positions[2].y() = std::numeric_limits<double>::quiet_NaN();
    m.positions[3].x() = std::numeric_limits<double>::infinity();
    expect_invalid(m, "positions[2] = (1, nan, 0)");
}

TEST(Mesh, ValidateRejectsIndexOutOfRange) {
    Mesh m = square_mesh();
    m.triangles[1][2] = 4;
    expect_invalid(m, "triangles[1][2] = 4; expected a vertex index in [0, 4)");
    m.triangles[1][2] = -1;
    expect_invalid(m, "triangles[1][2] = -1");
}

TEST(Mesh, ValidateRejectsBadOptionalArrays) {
    Mesh m = square_mesh();
    m.normals.pop_back();
    expect_invalid(m, "normals has 3 entries; expected 0 or 4");

    m = square_mesh();
    m.normals[1] *= 2.0;
    expect_invalid(m, "normals[1]");

    m = square_mesh();
    m.uvs[0].x() = std::numeric_limits<double>::quiet_NaN();
    expect_invalid(m, "uvs[0]");

    m = square_mesh();
    m.face_ids = {0};
    expect_invalid(m, "face_ids has 1 entries; expected 0 or 2");

    m = square_mesh();
    m.face_ids[1] = -3;
    expect_invalid(m, "face_ids[1] = -3");

    m = cube_mesh();
    m.face_colors.resize(5);
    expect_invalid(m, "face_ids[10] = 5 has no colour");

    m = cube_mesh();
    m.face_colors[2][1] = 1.5f;
    expect_invalid(m, "face_colors[2][1] = 1.5");
}

TEST(Mesh, ValidateRejectsBadEdges) {
    Mesh m = square_mesh();
    m.edges = {{0, 1, kFaceBoundary}, {2, 2, kSharp}};
    expect_invalid(m, "edges[1] joins vertex 2 to itself");
    m.edges = {{0, 1, 0}};
    expect_invalid(m, "edges[0] has flags 0");
    m.edges = {{0, 7, kSharp}};
    expect_invalid(m, "edges[0] uses vertex 7");
    m.edges = {{0, 1, kSharp}, {1, 0, kFaceBoundary}};
    expect_invalid(m, "edge (0, 1) is listed more than once");
}

TEST(Mesh, AppendOffsetsIndicesAndKeepsFaceIds) {
    Mesh into = square_mesh();
    into.edges = {{0, 1, kFaceBoundary}};
    Mesh part = cube_mesh(2.0);
    append(into, part);
    ASSERT_EQ(into.vertex_count(), 4u + 24u);
    ASSERT_EQ(into.triangle_count(), 2u + 12u);
    EXPECT_EQ(into.normals.size(), into.vertex_count());
    EXPECT_EQ(into.uvs.size(), into.vertex_count());
    EXPECT_EQ(into.face_ids.size(), into.triangle_count());
    for (std::size_t t = 0; t < part.triangles.size(); ++t) {
        for (int k = 0; k < 3; ++k) EXPECT_EQ(into.triangles[2 + t][k], part.triangles[t][k] + 4);
        EXPECT_EQ(into.face_ids[2 + t], part.face_ids[t]);
    }
    ASSERT_EQ(into.edges.size(), 1u + part.edges.size());
    EXPECT_EQ(into.edges[1].v0, part.edges[0].v0 + 4);
    EXPECT_EQ(into.face_colors.size(), 6u);
    EXPECT_NO_THROW(validate(into));
    EXPECT_NEAR(surface_area(into), 1.0 + 6 * 4.0, 1e-12);
}

TEST(Mesh, AppendIntoEmptyTakesPartArrays) {
    Mesh into;
    append(into, cube_mesh());
    EXPECT_EQ(into.vertex_count(), 24u);
    EXPECT_TRUE(into.has_normals());
    EXPECT_NO_THROW(validate(into));
}

TEST(Mesh, AppendWithMismatchedArraysThrowsAndLeavesIntoUnchanged) {
    Mesh into = square_mesh();
    Mesh part = square_mesh();
    part.uvs.clear();
    try {
        append(into, part);
        ADD_FAILURE() << "append accepted meshes with different arrays";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("uvs"), std::string::npos) << e.what();
    }
    EXPECT_EQ(into.vertex_count(), 4u);
    EXPECT_EQ(into.triangle_count(), 2u);
}

TEST(Mesh, SurfaceAreaAndBoundingBoxAtLargeAndSmallScales) {
    for (double s : {1e-6, 1.0, 1e6}) {
        const Eigen::Vector3d origin(3 * s, -2 * s, s);
        const Mesh m = cube_mesh(s, origin);
        EXPECT_NEAR(surface_area(m), 6 * s * s, 1e-12 * s * s) << "scale " << s;
        const Eigen::AlignedBox3d box = bounding_box(m);
        EXPECT_TRUE(box.min().isApprox(origin, 1e-12)) << "scale " << s;
        EXPECT_TRUE(box.max().isApprox(origin + Eigen::Vector3d::Constant(s), 1e-12))
            << "scale " << s;
    }
    EXPECT_TRUE(bounding_box(Mesh{}).isEmpty());
    EXPECT_EQ(surface_area(Mesh{}), 0.0);
}

// Four triangles of faces 0, 1, 2, 1 round a fan centre (vertex 0); faces 0 and 2 form
// group 0, face 1 group 1. Each part takes the vertices its triangles use, the centre
// copied into both, with their normals and (u,v); face ids and order are kept.
TEST(Mesh, SplitByFaceGroupRenumbersEachPartsVertices) {
    Mesh m;
    for (int k = 0; k < 6; ++k) {
        m.positions.emplace_back(k, k * k, 0);
        m.normals.emplace_back(0, 0, 1);
        m.uvs.emplace_back(k, -k);
    }
    m.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}};
    m.face_ids = {0, 1, 2, 1};
    const std::vector<Mesh> parts = split_by_face_group(m, {0, 1, 0}, 2);
    ASSERT_EQ(parts.size(), 2u);
    EXPECT_EQ(parts[0].triangles, (std::vector<std::array<std::int32_t, 3>>{{0, 1, 2}, {0, 3, 4}}));
    EXPECT_EQ(parts[0].face_ids, (std::vector<std::int32_t>{0, 2}));
    EXPECT_EQ(parts[0].positions, (std::vector<Eigen::Vector3d>{m.positions[0], m.positions[1], m.positions[2],
                                                               m.positions[3], m.positions[4]}));
    EXPECT_EQ(parts[1].triangles, (std::vector<std::array<std::int32_t, 3>>{{0, 1, 2}, {0, 3, 4}}));
    EXPECT_EQ(parts[1].face_ids, (std::vector<std::int32_t>{1, 1}));
    EXPECT_EQ(parts[1].uvs, (std::vector<Eigen::Vector2d>{m.uvs[0], m.uvs[2], m.uvs[3], m.uvs[4], m.uvs[5]}));
    EXPECT_EQ(parts[1].normals.size(), 5u);
    EXPECT_NO_THROW(validate(parts[0]));
    EXPECT_NO_THROW(validate(parts[1]));
    // A face without a group is an error naming the triangle.
    try {
        split_by_face_group(m, {0, 1}, 2);
        ADD_FAILURE() << "face 2 has no group";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("triangles[2] has face id 2"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace trimkit::mesh
