// Tests for tbp/from_mesh.h: PN triangles interpolate the mesh vertices with
// the vertex normals, a PN icosphere is watertight when polygonized (0 open
// edges after welding), encloses its centre, and lies close to the sphere.
#include "tbp/from_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
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

// The unit cube as 12 outward triangles on 8 shared vertices.
mesh::Mesh unit_cube() {
    mesh::Mesh m;
    for (int k = 0; k < 8; ++k) m.positions.push_back(Eigen::Vector3d(k & 1, (k >> 1) & 1, (k >> 2) & 1));
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) {
        m.triangles.push_back({q[0], q[1], q[2]});
        m.triangles.push_back({q[0], q[2], q[3]});
    }
    return m;
}

// Largest distance of a patch's control points from the plane of its corners.
double off_plane(const geom::BezierTriangle& patch) {
    const Eigen::Vector3d a = patch.corner(0), n = (patch.corner(1) - a).cross(patch.corner(2) - a).normalized();
    double worst = 0;
    for (const auto& p : patch.points()) worst = std::max(worst, std::abs((p - a).dot(n)));
    return worst;
}

// Sides meeting at more than the sharp angle stay creases: the cube's faces meet at
// 90 degrees, so at 30 degrees every patch is flat (the cube keeps its volume, 1),
// while smoothing every side bulges them; the diagonals inside each square face
// (0 degrees) stay smooth either way. The solid is closed in both cases.
TEST(PnTriangles, SharpSidesStayCreasesSoACubeStaysACube) {
    const mesh::Mesh cube = unit_cube();
    const TbpSolid sharp = pn_triangles(cube, 30.0 * M_PI / 180.0);
    const TbpSolid smooth = pn_triangles(cube);
    double sharp_worst = 0, smooth_worst = 0;
    for (const auto& p : sharp.patches) sharp_worst = std::max(sharp_worst, off_plane(p));
    for (const auto& p : smooth.patches) smooth_worst = std::max(smooth_worst, off_plane(p));
    EXPECT_LT(sharp_worst, 1e-15);
    EXPECT_GT(smooth_worst, 0.05);
    for (const TbpSolid* s : {&sharp, &smooth}) {
        PolygonizeOptions o;
        o.level = 2;
        o.lod = 1;
        const mesh::Mesh m = polygonize(*s, o);
        EXPECT_TRUE(mesh::open_edges(m).closed());
        // Volume by the divergence theorem over the polygonized triangles.
        double volume = 0;
        for (const auto& t : m.triangles)
            volume += m.positions[t[0]].dot(m.positions[t[1]].cross(m.positions[t[2]])) / 6.0;
        if (s == &sharp) EXPECT_NEAR(volume, 1.0, 1e-12);
        else EXPECT_GT(volume, 1.05);
    }
    EXPECT_THROW(pn_triangles(cube, -1.0), geom::InvalidInput);
    EXPECT_THROW(pn_triangles(cube, NAN), geom::InvalidInput);
}

// Volume by the divergence theorem over a polygonized solid's triangles.
double polygonized_volume(const TbpSolid& s) {
    PolygonizeOptions o;
    o.level = 2;
    o.lod = 1;
    const mesh::Mesh m = polygonize(s, o);
    EXPECT_TRUE(mesh::open_edges(m).closed());
    double volume = 0;
    for (const auto& t : m.triangles) volume += m.positions[t[0]].dot(m.positions[t[1]].cross(m.positions[t[2]])) / 6.0;
    return volume;
}

// Edges marked sharp (Blender's use_edge_sharp) are creases whatever the angle: with
// no side sharp by angle (pi), the cube's 12 edges given as vertex pairs keep every
// patch flat and the volume 1. The pairs index the input vertices, before welding: a
// cube whose faces have their own vertices (24) welds to 8 and gives the same solid.
// Marking only the 4 edges around the top face (z = 1) leaves the other 8 smooth,
// so the cube bulges less than when smoothed everywhere. A pair that is no side (a
// body diagonal) changes nothing; an index outside the mesh is invalid input.
TEST(PnTriangles, MarkedSharpEdgesStayCreasesWhateverTheAngle) {
    const mesh::Mesh cube = unit_cube();
    VertexPairs edges;
    for (int k = 0; k < 8; ++k)
        for (int bit : {1, 2, 4})
            if (!(k & bit)) edges.emplace_back(k, k | bit);
    ASSERT_EQ(edges.size(), 12u);
    const TbpSolid marked = pn_triangles(cube, kNoSharpEdges, edges);
    double worst = 0;
    for (const auto& p : marked.patches) worst = std::max(worst, off_plane(p));
    EXPECT_LT(worst, 1e-15);
    EXPECT_NEAR(polygonized_volume(marked), 1.0, 1e-12);

    // Reversed pairs and the face-split input: vertex 4 q + c is corner c of quad q.
    mesh::Mesh split;
    VertexPairs split_edges;
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (int q = 0; q < 6; ++q) {
        for (int c = 0; c < 4; ++c) split.positions.push_back(cube.positions[quads[q][c]]);
        split.triangles.push_back({4 * q, 4 * q + 1, 4 * q + 2});
        split.triangles.push_back({4 * q, 4 * q + 2, 4 * q + 3});
        for (int c = 0; c < 4; ++c) split_edges.emplace_back(4 * q + (c + 1) % 4, 4 * q + c);
    }
    EXPECT_NEAR(polygonized_volume(pn_triangles(split, kNoSharpEdges, split_edges)), 1.0, 1e-12);

    VertexPairs top;  // the square z = 1: vertices 4..7
    for (const auto& e : edges)
        if ((e.first & 4) && (e.second & 4)) top.push_back(e);
    ASSERT_EQ(top.size(), 4u);
    const double smooth = polygonized_volume(pn_triangles(cube));
    const double partly = polygonized_volume(pn_triangles(cube, kNoSharpEdges, top));
    EXPECT_GT(partly, 1.0 + 1e-3);
    EXPECT_LT(partly, smooth - 1e-3);

    const TbpSolid diagonal = pn_triangles(cube, kNoSharpEdges, {{0, 7}});
    const TbpSolid none = pn_triangles(cube);
    for (std::size_t k = 0; k < none.patches.size(); ++k)
        EXPECT_EQ(diagonal.patches[k].points(), none.patches[k].points());
    EXPECT_THROW(pn_triangles(cube, kNoSharpEdges, {{0, 8}}), geom::InvalidInput);
    EXPECT_THROW(pn_triangles(cube, kNoSharpEdges, {{-1, 2}}), geom::InvalidInput);
}

// Below every side's angle the sharp angle changes nothing: an icosphere's faces meet
// at about 20 degrees (level 1), so a sharp angle of 30 degrees gives the smooth solid.
TEST(PnTriangles, SharpAngleAboveEverySideChangesNothing) {
    const mesh::Mesh ico = test::icosphere(1);
    const TbpSolid a = pn_triangles(ico), b = pn_triangles(ico, 30.0 * M_PI / 180.0);
    ASSERT_EQ(a.patches.size(), b.patches.size());
    for (std::size_t k = 0; k < a.patches.size(); ++k)
        for (std::size_t i = 0; i < a.patches[k].points().size(); ++i)
            EXPECT_EQ(a.patches[k].points()[i], b.patches[k].points()[i]);
}

}  // namespace
}  // namespace trimkit::tbp
