// Tests for tbp/polygonize.h: the domain pattern (counts, orientation, exact
// edge parameters), and a watertight, outward-oriented mesh of the unit cube
// made of 12 flat cubic TBPs.
#include "tbp/polygonize.h"

#include <gtest/gtest.h>

#include "geom/error.h"
#include "mesh/open_edges.h"
#include "mesh/weld_vertices.h"
#include "tbp_samples.h"

namespace trimkit::tbp {
namespace {

double signed_volume(const mesh::Mesh& m) {
    double v = 0;
    for (const auto& t : m.triangles)
        v += m.positions[t[0]].dot(m.positions[t[1]].cross(m.positions[t[2]])) / 6.0;
    return v;
}

TEST(TrianglePattern, CountsOrientationAndCorners) {
    for (int rate : {1, 2, 3, 8, 27}) {
        const DomainPattern p = triangle_pattern(rate);
        EXPECT_EQ(p.points.size(), static_cast<std::size_t>((rate + 1) * (rate + 2) / 2));
        EXPECT_EQ(p.triangles.size(), static_cast<std::size_t>(rate * rate));
        EXPECT_EQ(p.points[0], Eigen::Vector3d(1, 0, 0));
        EXPECT_EQ(p.points[rate], Eigen::Vector3d(0, 1, 0));
        EXPECT_EQ(p.points[2 * rate], Eigen::Vector3d(0, 0, 1));
        for (const auto& t : p.triangles) {
            const Eigen::Vector3d a = p.points[t[0]], b = p.points[t[1]], c = p.points[t[2]];
            const double area = 0.5 * ((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x());
            EXPECT_NEAR(area, 0.5 / (rate * rate), 1e-14);
        }
    }
    EXPECT_THROW(triangle_pattern(0), geom::InvalidInput);
    EXPECT_EQ(polygonize_rate(2, 3), 16);
    EXPECT_THROW(polygonize_rate(20, 3), geom::InvalidInput);
}

TEST(Polygonize, CubeOfFlatPatchesIsWatertight) {
    const TbpSolid cube = test::box_solid();
    for (int level : {0, 1, 2}) {
        PolygonizeOptions o;
        o.level = level;
        o.lod = 2;
        const mesh::Mesh m = polygonize(cube, o);
        mesh::validate(m);
        const int rate = polygonize_rate(level, 2);
        EXPECT_EQ(m.triangle_count(), 12u * rate * rate);
        const mesh::OpenEdges e = mesh::open_edges(m);
        EXPECT_TRUE(e.closed()) << e.boundary.size() << " open edges";
        EXPECT_TRUE(e.misoriented.empty());
        EXPECT_NEAR(mesh::surface_area(m), 6.0, 1e-12);
        EXPECT_NEAR(signed_volume(m), 1.0, 1e-12);  // positive: normals point out
        // Euler characteristic of a sphere
        EXPECT_EQ(static_cast<long>(m.vertex_count()) - static_cast<long>(m.triangle_count()) / 2, 2);
    }
}

TEST(Polygonize, NormalsAndUvsComeFromThePatch) {
    const TbpPatch p = test::flat_patch({0, 0, 0}, {2, 0, 0}, {0, 3, 0});
    const mesh::Mesh m = polygonize_patch(p, 4, 7);
    for (std::size_t v = 0; v < m.vertex_count(); ++v) {
        const Eigen::Vector3d t(m.uvs[v].x(), m.uvs[v].y(), 1 - m.uvs[v].x() - m.uvs[v].y());
        EXPECT_LT((p.evaluate(t) - m.positions[v]).norm(), 1e-15);
        EXPECT_NEAR(m.normals[v].z(), 1.0, 1e-15);  // corners u, v, w counter-clockwise seen from +z
    }
    EXPECT_EQ(m.face_ids.front(), 7);
}

// tests/fuzz/regressions/tbp/collapsed_patch.tbp: a patch whose corners lie on one
// line has no normal anywhere; polygonize reports it as bad input naming the patch.
TEST(Polygonize, PatchWithoutAreaIsInvalidInputNamingThePatch) {
    TbpSolid solid;
    solid.patches.push_back(test::flat_patch({0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
    solid.patches.push_back(test::flat_patch({0, 0, 0}, {0, 1, 0}, {0, 1, 0}));
    PolygonizeOptions options;
    options.level = 1;
    options.lod = 1;
    try {
        polygonize(solid, options);
        ADD_FAILURE() << "no error for a patch without area";
    } catch (const geom::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("polygonize: patch 1 is degenerate"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace trimkit::tbp
