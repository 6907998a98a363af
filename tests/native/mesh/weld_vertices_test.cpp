#include "mesh/weld_vertices.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "geom/error.h"
#include "mesh/open_edges.h"
#include "mesh/sample_meshes.h"

namespace trimkit::mesh {
namespace {

using test::cube_mesh;
using test::square_mesh;

// Moves every vertex by a pseudo-random offset of length < `jitter`.
void jitter_positions(Mesh& m, double jitter, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> d(-1.0, 1.0);
    for (auto& p : m.positions) {
        Eigen::Vector3d offset(d(rng), d(rng), d(rng));
        if (offset.norm() > 1.0) offset.normalize();
        p += 0.99 * jitter * offset;
    }
}

// The mesh with vertices listed in the order `perm` (new vertex i = old perm[i]).
Mesh permute_vertices(const Mesh& m, const std::vector<std::int32_t>& perm) {
    Mesh out = m;
    std::vector<std::int32_t> inverse(perm.size());
    for (std::size_t i = 0; i < perm.size(); ++i) {
        inverse[perm[i]] = static_cast<std::int32_t>(i);
        out.positions[i] = m.positions[perm[i]];
        out.normals[i] = m.normals[perm[i]];
        out.uvs[i] = m.uvs[perm[i]];
    }
    for (auto& t : out.triangles)
        for (auto& v : t) v = inverse[v];
    for (auto& e : out.edges) {
        e.v0 = inverse[e.v0];
        e.v1 = inverse[e.v1];
    }
    return out;
}

TEST(WeldVertices, CubeOfSixQuadsWeldsToEightVerticesAndNoOpenEdges) {
    Mesh m = cube_mesh();
    EXPECT_EQ(count_open_edges(m), 24u);  // before welding every quad is open
    const WeldResult r = weld_vertices(m, {1e-9});
    EXPECT_EQ(r.vertex_count, 8);
    EXPECT_EQ(r.removed_triangles, 0);
    EXPECT_EQ(m.vertex_count(), 8u);
    EXPECT_EQ(m.triangle_count(), 12u);
    EXPECT_EQ(m.normals.size(), 8u);
    EXPECT_EQ(m.face_ids.size(), 12u);
    const OpenEdges open = open_edges(m);
    EXPECT_EQ(open.boundary.size(), 0u);
    EXPECT_EQ(open.non_manifold.size(), 0u);
    EXPECT_EQ(open.misoriented.size(), 0u);
    EXPECT_TRUE(open.closed());
    // Each of the 12 cube edges is a boundary of two faces: 24 flagged uses merge to 12.
    EXPECT_EQ(m.edges.size(), 12u);
    EXPECT_NEAR(surface_area(m), 6.0, 1e-12);
    EXPECT_NO_THROW(validate(m));
}

TEST(WeldVertices, WeldsAtLargeAndSmallScales) {
    for (double s : {1e-6, 1.0, 1e6}) {
        Mesh m = cube_mesh(s, Eigen::Vector3d(5 * s, -7 * s, 11 * s));
        const double tolerance = 1e-6 * s;
        jitter_positions(m, 0.4 * tolerance, 17);  // duplicates now differ by < 0.8 tolerance
        const WeldResult r = weld_vertices(m, {tolerance});
        EXPECT_EQ(r.vertex_count, 8) << "scale " << s;
        EXPECT_EQ(count_open_edges(m), 0u) << "scale " << s;
    }
}

TEST(WeldVertices, VerticesFartherThanToleranceStaySeparate) {
    for (double s : {1e-6, 1.0, 1e6}) {
        Mesh m = cube_mesh(s);
        const WeldResult r = weld_vertices(m, {0.5 * s});  // edge length s > tolerance
        EXPECT_EQ(r.vertex_count, 8) << "scale " << s;
        Mesh separate = cube_mesh(s);
        for (std::size_t i = 0; i < separate.positions.size(); ++i)
            separate.positions[i] += 1e-3 * s * Eigen::Vector3d::Constant(static_cast<double>(i));
        EXPECT_EQ(weld_map(separate, {1e-4 * s}).vertex_count, 24) << "scale " << s;
    }
}

TEST(WeldVertices, ZeroToleranceMergesExactDuplicatesOnly) {
    Mesh m = cube_mesh();
    EXPECT_EQ(weld_map(m, {0.0}).vertex_count, 8);
    m.positions[0].x() += 1e-15;
    EXPECT_EQ(weld_map(m, {0.0}).vertex_count, 9);
}

TEST(WeldVertices, MapIsIdentityWithoutCloseVertices) {
    const Mesh m = square_mesh();
    const WeldResult r = weld_map(m, {0.1});
    EXPECT_EQ(r.vertex_map, (std::vector<std::int32_t>{0, 1, 2, 3}));
    EXPECT_EQ(r.vertex_count, 4);
}

TEST(WeldVertices, ResultDoesNotDependOnVertexOrder) {
    Mesh m = cube_mesh();
    jitter_positions(m, 1e-7, 3);
    std::vector<std::int32_t> perm(m.vertex_count());
    std::iota(perm.begin(), perm.end(), 0);
    std::shuffle(perm.begin(), perm.end(), std::mt19937(5));
    Mesh shuffled = permute_vertices(m, perm);

    const WeldResult a = weld_map(m, {1e-6});
    const WeldResult b = weld_map(shuffled, {1e-6});
    ASSERT_EQ(a.vertex_count, b.vertex_count);
    // Same partition, and each welded vertex at the same position.
    Mesh wa = m, wb = shuffled;
    weld_vertices(wa, {1e-6});
    weld_vertices(wb, {1e-6});
    for (std::size_t i = 0; i < perm.size(); ++i) {
        const Eigen::Vector3d& pa = wa.positions[a.vertex_map[perm[i]]];
        const Eigen::Vector3d& pb = wb.positions[b.vertex_map[i]];
        EXPECT_EQ(pa, pb) << "vertex " << perm[i];
    }
}

TEST(WeldVertices, KeepSplitNormalsLeavesCreasesUnwelded) {
    Mesh m = cube_mesh();
    WeldOptions options{1e-9};
    options.keep_split_normals = true;
    options.split_normal_angle = 0.1;
    const WeldResult r = weld_vertices(m, options);
    EXPECT_EQ(r.vertex_count, 24);  // every corner has three different normals

    // Two coplanar triangles sharing an edge with equal normals do weld.
    Mesh square = square_mesh();
    Mesh split;
    split.positions = {square.positions[0], square.positions[1], square.positions[2],
                       square.positions[0], square.positions[2], square.positions[3]};
    split.normals.assign(6, Eigen::Vector3d::UnitZ());
    split.triangles = {{0, 1, 2}, {3, 4, 5}};
    EXPECT_EQ(weld_vertices(split, options).vertex_count, 4);
    EXPECT_EQ(count_open_edges(split), 4u);
}

TEST(WeldVertices, KeepsRepresentativeAttributes) {
    Mesh m = cube_mesh();
    weld_vertices(m, {1e-9});
    for (std::size_t i = 0; i < m.vertex_count(); ++i) {
        // Each welded normal is one of the three outward face normals at its corner.
        const Eigen::Vector3d outward = (m.positions[i] - Eigen::Vector3d::Constant(0.5)) * 2.0;
        EXPECT_NEAR(m.normals[i].norm(), 1.0, 1e-15);
        EXPECT_NEAR(m.normals[i].dot(outward), 1.0, 1e-12);
    }
}

TEST(WeldVertices, LargeToleranceRemovesDegenerateTriangles) {
    Mesh m = square_mesh(1.0);
    m.positions.push_back({0.5, 0.5, 0.0});
    m.positions.push_back({0.5, 0.5 + 1e-4, 0.0});
    m.normals.assign(6, Eigen::Vector3d::UnitZ());
    m.uvs.resize(6, Eigen::Vector2d(0.5, 0.5));
    m.triangles.push_back({4, 5, 0});
    m.face_ids.push_back(1);
    const WeldResult r = weld_vertices(m, {1e-3});
    EXPECT_EQ(r.vertex_count, 5);
    EXPECT_EQ(r.removed_triangles, 1);
    EXPECT_EQ(m.triangle_count(), 2u);
    EXPECT_EQ(m.face_ids, (std::vector<std::int32_t>{0, 0}));
}

TEST(WeldVertices, RejectsBadToleranceAndLeavesMeshUnchanged) {
    Mesh m = cube_mesh();
    EXPECT_THROW(weld_vertices(m, {-1.0}), geom::InvalidInput);
    EXPECT_THROW(weld_vertices(m, {std::numeric_limits<double>::quiet_NaN()}),
                 geom::InvalidInput);
    EXPECT_EQ(m.vertex_count(), 24u);
    m.triangles[0][0] = 99;
    EXPECT_THROW(weld_vertices(m, {1e-9}), geom::InvalidInput);
    EXPECT_EQ(m.vertex_count(), 24u);
}

}  // namespace
}  // namespace trimkit::mesh
