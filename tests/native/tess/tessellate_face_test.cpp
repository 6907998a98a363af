#include "tess/tessellate_face.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <set>

#include "geom/error.h"
#include "mesh/open_edges.h"
#include "surface_test_support.h"
#include "test_support.h"

namespace trimkit::tess {
namespace {

using test::bicubic_patch;
using test::circle_loop;
using test::rectangle_loop;

// A bicubic patch with a circular hole, the trim polygons fine enough that their
// chord error is far below the tolerance.
std::vector<TrimPolygon> holed_loops(const geom::NurbsSurface& S) {
    return {rectangle_loop(S, 0, 1, 0, 1, 200), circle_loop(S, 0.45, 0.55, 0.2, 400)};
}

// Every open edge of a face mesh must be a flagged face-boundary edge.
void expect_open_edges_on_boundary(const mesh::Mesh& m) {
    std::set<std::pair<int, int>> flagged;
    for (const auto& e : m.edges)
        if (e.flags & mesh::kFaceBoundary) flagged.emplace(std::min(e.v0, e.v1), std::max(e.v0, e.v1));
    const auto open = mesh::open_edges(m);
    EXPECT_FALSE(open.boundary.empty());
    int inside = 0;
    for (const auto& e : open.boundary)
        if (!flagged.count({std::min(e[0], e[1]), std::max(e[0], e[1])})) ++inside;
    EXPECT_EQ(inside, 0) << "open edges inside the face";
    EXPECT_TRUE(open.non_manifold.empty());
    EXPECT_TRUE(open.misoriented.empty());
}

// Normals unit, pointing to the side the triangle's winding says.
void expect_normals_match_winding(const mesh::Mesh& m) {
    int against = 0;
    for (const auto& t : m.triangles) {
        const Eigen::Vector3d g = (m.positions[t[1]] - m.positions[t[0]])
                                      .cross(m.positions[t[2]] - m.positions[t[0]]);
        if (g.norm() < 1e-12) continue;
        const Eigen::Vector3d n = m.normals[t[0]] + m.normals[t[1]] + m.normals[t[2]];
        if (g.dot(n) <= 0.0) ++against;
    }
    EXPECT_EQ(against, 0);
    for (const auto& n : m.normals) EXPECT_NEAR(n.norm(), 1.0, 1e-9);
}

TEST(TessellateFace, BicubicWithHoleWithinToleranceAndArea) {
    const auto S = bicubic_patch();
    const auto loops = holed_loops(S);
    for (double tol : {1e-2, 1e-3}) {
        TessellationOptions options;
        options.tolerance = tol;
        const mesh::Mesh m = tessellate_face(test::face_of(S), loops, options, 7);
        mesh::validate(m);
        ASSERT_GT(m.triangle_count(), 0u);
        for (const auto& p : m.positions) EXPECT_TRUE(trimkit::test::is_finite(p));
        const double deviation = test::parametric_deviation(m, S);
        const double distance = test::surface_distance(m, S);
        const double exact = test::trimmed_area(S, loops, 1000);
        const double area = mesh::surface_area(m);
        std::printf("bicubic hole tol %g: %zu triangles, deviation %.3g, distance %.3g, area %.6f vs %.6f\n",
                    tol, m.triangle_count(), deviation, distance, area, exact);
        EXPECT_LE(deviation, tol);
        EXPECT_LE(distance, tol);
        EXPECT_NEAR(area / exact, 1.0, 2e-3);
        for (int id : m.face_ids) EXPECT_EQ(id, 7);
        expect_open_edges_on_boundary(m);
        expect_normals_match_winding(m);
    }
}

TEST(TessellateFace, RationalPatchWithinTolerance) {
    const auto S = bicubic_patch(1.0, true);
    TessellationOptions options;
    options.tolerance = 2e-3;
    const mesh::Mesh m = tessellate_face(test::face_of(S), holed_loops(S), options, 0);
    const double deviation = test::parametric_deviation(m, S);
    std::printf("rational: %zu triangles, deviation %.3g\n", m.triangle_count(), deviation);
    EXPECT_LE(deviation, options.tolerance);
    expect_open_edges_on_boundary(m);
}

TEST(TessellateFace, ApproximateModeUsesFewerTriangles) {
    const auto S = bicubic_patch();
    TessellationOptions options;
    options.tolerance = 1e-3;
    const mesh::Mesh guaranteed = tessellate_face(test::face_of(S), holed_loops(S), options, 0);
    options.mode = ErrorMode::kApproximate;
    const mesh::Mesh approximate = tessellate_face(test::face_of(S), holed_loops(S), options, 0);
    const double deviation = test::parametric_deviation(approximate, S);
    std::printf("guaranteed %zu triangles, approximate %zu (deviation %.3g)\n",
                guaranteed.triangle_count(), approximate.triangle_count(), deviation);
    EXPECT_LT(approximate.triangle_count(), guaranteed.triangle_count());
    EXPECT_LE(deviation, 2.0 * options.tolerance);  // an estimate, not a bound
}

TEST(TessellateFace, BilinearPatchTwist) {
    const auto S = test::bilinear_patch();
    TessellationOptions options;
    options.tolerance = 1e-3;
    const mesh::Mesh m = tessellate_face(test::face_of(S), {rectangle_loop(S, 0, 1, 0, 1, 3)}, options, 0);
    EXPECT_LE(test::parametric_deviation(m, S), options.tolerance);
    EXPECT_NEAR(mesh::surface_area(m), test::trimmed_area(S, {rectangle_loop(S, 0, 1, 0, 1, 3)}, 600), 1e-3);
    expect_open_edges_on_boundary(m);
}

TEST(TessellateFace, SameCaseAtTinyAndHugeScale) {
    for (double scale : {1e-6, 1e6}) {
        const auto S = bicubic_patch(scale);
        TessellationOptions options;
        options.tolerance = 1e-3 * scale;
        const mesh::Mesh m = tessellate_face(test::face_of(S), holed_loops(S), options, 0);
        EXPECT_LE(test::parametric_deviation(m, S), options.tolerance) << "scale " << scale;
        expect_open_edges_on_boundary(m);
    }
}

TEST(TessellateFace, ReversedFaceFlipsNormalsAndWinding) {
    const auto S = bicubic_patch();
    TessellationOptions options;
    options.tolerance = 1e-2;
    const mesh::Mesh a = tessellate_face(test::face_of(S, false), holed_loops(S), options, 0);
    const mesh::Mesh b = tessellate_face(test::face_of(S, true), holed_loops(S), options, 0);
    ASSERT_EQ(a.vertex_count(), b.vertex_count());
    ASSERT_EQ(a.triangle_count(), b.triangle_count());
    for (size_t i = 0; i < a.vertex_count(); ++i) EXPECT_TRUE(a.normals[i].isApprox(-b.normals[i]));
    EXPECT_EQ(a.triangles[0][1], b.triangles[0][2]);
    expect_normals_match_winding(a);
    expect_normals_match_winding(b);
}

TEST(TessellateFace, SmallHoleInsideOneCellAndIslandFace) {
    // A plane: one cell; the hole lies inside it and must be bridged, not lost.
    const geom::NurbsSurface plane(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2,
                                   {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}});
    TessellationOptions options;
    options.tolerance = 1e-3;
    const std::vector<TrimPolygon> loops = {rectangle_loop(plane, 0, 1, 0, 1, 1),
                                            circle_loop(plane, 0.5, 0.5, 0.1, 64)};
    const mesh::Mesh m = tessellate_face(test::face_of(plane), loops, options, 0);
    const double hole = 64 * 0.5 * 0.01 * std::sin(2 * M_PI / 64);
    EXPECT_NEAR(mesh::surface_area(m), 1.0 - hole, 1e-12);
    expect_open_edges_on_boundary(m);
    // A face whose only loop lies inside one cell.
    const mesh::Mesh island = tessellate_face(test::face_of(plane), {circle_loop(plane, 0.3, 0.6, 0.2, 50, true)},
                                              options, 0);
    EXPECT_NEAR(mesh::surface_area(island), 50 * 0.5 * 0.04 * std::sin(2 * M_PI / 50), 1e-12);
}

TEST(TessellateFace, TrimAlongGridLinesAndCorners) {
    // Loops whose sides lie on patch boundaries (u = 0.5 is a knot) and pass cell corners.
    const auto base = bicubic_patch();
    const auto S = base.insert_knot_u(0.5).insert_knot_v(0.5);
    TessellationOptions options;
    options.tolerance = 5e-3;
    const std::vector<TrimPolygon> loops = {rectangle_loop(S, 0.0, 0.5, 0.0, 0.5, 10)};
    const mesh::Mesh m = tessellate_face(test::face_of(S), loops, options, 0);
    EXPECT_LE(test::parametric_deviation(m, S), options.tolerance);
    EXPECT_NEAR(mesh::surface_area(m) / test::trimmed_area(S, loops, 1000), 1.0, 3e-3);
    expect_open_edges_on_boundary(m);
}

TEST(TessellateFace, RejectsBadInput) {
    const auto S = bicubic_patch();
    TessellationOptions options;
    options.tolerance = 0.0;
    EXPECT_THROW(tessellate_face(test::face_of(S), holed_loops(S), options, 0), geom::InvalidInput);
    options.tolerance = 1e-3;
    auto loops = holed_loops(S);
    loops[1].points[3].uv.x() = std::nan("");
    EXPECT_THROW(tessellate_face(test::face_of(S), loops, options, 3), geom::InvalidInput);
    // Degenerate loop: all points on a line.
    TrimPolygon line;
    line.outer = true;
    for (int k = 0; k < 5; ++k) line.points.push_back(test::on_surface(S, 0.1 * k, 0.3));
    try {
        tessellate_face(test::face_of(S), {line}, options, 5);
        FAIL() << "expected NumericalFailure";
    } catch (const geom::NumericalFailure& e) {
        EXPECT_NE(std::string(e.what()).find("face 5"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace trimkit::tess
