// Tests for tbp/from_mesh.h: PN triangles interpolate the mesh vertices with
// the vertex normals, a PN icosphere is watertight when polygonized (0 open
// edges after welding), encloses its centre, and lies close to the sphere.
#include "tbp/from_mesh.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "geom/error.h"
#include "mesh/open_edges.h"
#include "tbp/point_in_solid.h"
#include "tbp/polygonize.h"
#include "tbp_samples.h"

namespace trimkit::tbp {
namespace {

TEST(PnTriangles, IcosphereIsWatertightAndNearTheSphere) {
    const mesh::Mesh ico = test::icosphere(1);
    const TbpSolid s = pn_triangles(ico);
    ASSERT_EQ(s.patches.size(), ico.triangle_count());
    for (int level : {1, 2, 3}) {
        PolygonizeOptions o;
        o.level = level;
        o.lod = 1;
        const mesh::Mesh m = polygonize(s, o);
        const mesh::OpenEdges e = mesh::open_edges(m);
        EXPECT_TRUE(e.closed()) << e.boundary.size() << " open edges at level " << level;
        EXPECT_TRUE(e.misoriented.empty());
        double worst = 0;
        for (const auto& p : m.positions) worst = std::max(worst, std::abs(p.norm() - 1));
        EXPECT_LT(worst, 0.01);  // PN triangles of an 80-face icosphere: within 1% of the sphere
        for (std::size_t v = 0; v < m.vertex_count(); ++v) EXPECT_GT(m.normals[v].dot(m.positions[v]), 0.9);
    }
    // corners interpolate the vertices; corner normals are the vertex normals (radial here)
    EXPECT_NEAR(s.patches[0].corner(0).norm(), 1.0, 1e-15);
    EXPECT_GT(s.patches[0].normal({1, 0, 0}).dot(s.patches[0].corner(0)), 0.999);
    const std::vector<TbpHierarchy> h = build_hierarchies(s, 1, 2);
    EXPECT_EQ(point_in_solid(h, Eigen::Vector3d(0.1, 0.2, -0.1)), Containment::kInside);
    EXPECT_EQ(point_in_solid(h, Eigen::Vector3d(0.1, 1.2, -0.1)), Containment::kOutside);
}

TEST(PnTriangles, FlatMeshGivesFlatPatches) {
    mesh::Mesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.triangles = {{0, 1, 2}};
    const TbpSolid s = pn_triangles(m);
    for (const auto& p : s.patches[0].points()) EXPECT_NEAR(p.z(), 0.0, 1e-15);
    EXPECT_THROW(pn_triangles(mesh::Mesh{}), geom::InvalidInput);
}

// tests/fuzz/regressions/obj/cancelling_triangles.obj: a triangle and its reverse
// share every vertex, so no vertex has a normal. That is bad input (exit 2 in the
// CLI), not an internal failure.
TEST(PnTriangles, TrianglesThatCancelAreInvalidInputNamingTheVertex) {
    mesh::Mesh m;
    m.positions = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    m.triangles = {{0, 2, 1}, {0, 1, 2}};
    try {
        pn_triangles(m);
        ADD_FAILURE() << "no error for cancelling triangles";
    } catch (const geom::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("pn_triangles: vertex 0 has no normal"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace trimkit::tbp

namespace trimkit::tbp {
namespace {

TEST(LoopQuartics, RegularFacesAreExactAndSolidIsWatertight) {
    const mesh::Mesh cage = test::icosphere(2);  // 320 faces; 12 vertices of valence 5
    LoopConversion c;
    try {
        c = loop_quartics(cage);
    } catch (const geom::NumericalFailure& e) {
        GTEST_SKIP() << e.what();
    }
    ASSERT_EQ(c.solid.patches.size(), 320u);
    EXPECT_EQ(c.solid.degree(), 4);
    // faces with a valence-5 corner (5 around each of the 12) are approximated, the rest exact
    EXPECT_EQ(c.approximated, 60);
    EXPECT_GT(c.max_error, 0.0);
    EXPECT_LT(c.max_error, 1e-2);
    std::printf("Loop -> quartic TBPs: %d of 320 patches approximated, max error %.3g\n", c.approximated, c.max_error);
    PolygonizeOptions o;
    o.level = 2;
    o.lod = 1;
    const mesh::Mesh m = polygonize(c.solid, o);
    EXPECT_TRUE(mesh::open_edges(m).closed());
    double volume = 0;
    for (const auto& t : m.triangles) volume += m.positions[t[0]].dot(m.positions[t[1]].cross(m.positions[t[2]])) / 6;
    EXPECT_GT(volume, 3.0);  // outward orientation; a Loop limit shrinks the unit sphere (4.19) a little
}

}  // namespace
}  // namespace trimkit::tbp
