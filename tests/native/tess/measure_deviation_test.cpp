// measure_deviation against meshes built by hand from analytic surfaces, where
// the chord error, the offset and the exact area are known in closed form.
#include "tess/measure_deviation.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geom/analytic_surfaces.h"
#include "geom/error.h"

namespace trimkit::tess {
namespace {

geom::Model model_of(const geom::NurbsSurface& S) {
    geom::Model model;
    geom::Face face;
    face.surface = S;
    face.loops = {geom::natural_boundary_loop(S)};
    model.faces.push_back(face);
    return model;
}

// (nu+1) x (nv+1) vertices on S at a uniform (u,v) grid, two triangles per cell,
// each vertex moved by `offset` along the unit normal.
mesh::Mesh grid_mesh(const geom::NurbsSurface& S, int nu, int nv, double offset = 0.0) {
    mesh::Mesh m;
    const auto [u0, u1] = S.domain_u();
    const auto [v0, v1] = S.domain_v();
    for (int i = 0; i <= nu; ++i)
        for (int j = 0; j <= nv; ++j) {
            const double u = u0 + (u1 - u0) * i / nu, v = v0 + (v1 - v0) * j / nv;
            const Eigen::Vector3d n = S.normal(u, v);
            m.positions.push_back(S.evaluate(u, v) + offset * n);
            m.normals.push_back(n);
            m.uvs.emplace_back(u, v);
        }
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            const int a = i * (nv + 1) + j, b = a + nv + 1;
            m.triangles.push_back({a, b, b + 1});
            m.triangles.push_back({a, b + 1, a + 1});
            m.face_ids.push_back(0);
            m.face_ids.push_back(0);
        }
    return m;
}

const Eigen::Vector3d kOrigin(0.5, -1.0, 2.0), kAxis(0, 0, 1), kRef(1, 0, 0);

TEST(MeasureDeviation, CylinderFacetsShowTheSagitta) {
    const double r = 2.0, dtheta = (M_PI / 2) / 8;
    const geom::NurbsSurface S = geom::cylinder_patch(kOrigin, kAxis, kRef, r, 0.0, M_PI / 2, 0.0, 3.0);
    // Vertices at equal angles (the NURBS parameter is the angle at the grid's knots only,
    // so place them by angle), straight along z.
    mesh::Mesh m = grid_mesh(S, 8, 3);
    for (int i = 0; i <= 8; ++i)
        for (int j = 0; j <= 3; ++j) {
            const double theta = dtheta * i;
            m.positions[i * 4 + j] = kOrigin + Eigen::Vector3d(r * std::cos(theta), r * std::sin(theta), j);
        }
    DeviationOptions options;
    options.samples = 6;
    const DeviationReport report = measure_deviation(model_of(S), m, options);
    const double sagitta = r * (1 - std::cos(dtheta / 2));
    EXPECT_NEAR(report.mesh_to_surface.max, sagitta, 0.01 * sagitta);
    EXPECT_NEAR(report.surface_to_mesh.max, sagitta, 0.01 * sagitta);
    EXPECT_EQ(report.open_edges, 2u * (8 + 3));
}

}  // namespace
}  // namespace trimkit::tess
namespace trimkit::tess {
namespace {

TEST(MeasureDeviation, OffsetMeshReportsTheOffset) {
    const geom::NurbsSurface plane = geom::plane_patch(kOrigin, {1, 0.2, 0}, {0, 1, 0.3}, 0, 2, 0, 1);
    const DeviationReport flat = measure_deviation(model_of(plane), grid_mesh(plane, 6, 4, 0.01));
    EXPECT_NEAR(flat.mesh_to_surface.max, 0.01, 1e-6);
    EXPECT_NEAR(flat.mesh_to_surface.mean, 0.01, 1e-6);
    EXPECT_NEAR(flat.surface_to_mesh.max, 0.01, 1e-6);
    EXPECT_NEAR(flat.mesh_to_surface_max_uv, 0.01, 1e-6);

    // On a sphere the offset vertices are farthest: exactly 0.01 (chords come closer).
    const geom::NurbsSurface sphere = geom::sphere_patch(kOrigin, kAxis, kRef, 1.5, 0.0, M_PI / 2, 0.1, 0.9);
    const DeviationReport round = measure_deviation(model_of(sphere), grid_mesh(sphere, 48, 24, 0.01));
    EXPECT_NEAR(round.mesh_to_surface.max, 0.01, 1e-6);
}

TEST(MeasureDeviation, MissingTriangleShowsAHoleAndOpenEdges) {
    const geom::NurbsSurface S = geom::cylinder_patch(kOrigin, kAxis, kRef, 1.0, 0.0, M_PI, 0.0, 1.0);
    mesh::Mesh m = grid_mesh(S, 16, 4);
    const DeviationReport whole = measure_deviation(model_of(S), m);
    m.triangles.erase(m.triangles.begin() + 37);
    m.face_ids.erase(m.face_ids.begin() + 37);
    const DeviationReport holed = measure_deviation(model_of(S), m);
    EXPECT_GT(holed.surface_to_mesh.max, 3 * whole.surface_to_mesh.max);
    EXPECT_GT(holed.open_edges, whole.open_edges);
    EXPECT_LT(holed.area_ratio, whole.area_ratio);
}

TEST(MeasureDeviation, SpherePatchAreaMatchesClosedForm) {
    const double r = 2.0, phi0 = -0.3, phi1 = 0.8, dtheta = 1.2;
    const geom::NurbsSurface S = geom::sphere_patch(kOrigin, kAxis, kRef, r, 0.2, 0.2 + dtheta, phi0, phi1);
    const DeviationReport report = measure_deviation(model_of(S), grid_mesh(S, 96, 96));
    const double exact = 2 * M_PI * r * r * (std::sin(phi1) - std::sin(phi0)) * dtheta / (2 * M_PI);
    EXPECT_NEAR(report.area_exact, exact, 1e-6 * exact);
    EXPECT_NEAR(report.area_ratio, 1.0, 1e-3);
}

TEST(MeasureDeviation, TrimmedAreaOfADiscOnAPlane) {
    const geom::NurbsSurface S = geom::plane_patch({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0, 1, 0, 1);
    geom::Face face;
    face.surface = S;
    // A rational quadratic full circle of radius 0.3 around (0.5, 0.5), [PT] Sec. 7.5.
    const double w = std::sqrt(0.5);
    std::vector<Eigen::Vector2d> P;
    const double c[9][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
    for (const auto& q : c) P.emplace_back(0.5 + 0.3 * q[0], 0.5 + 0.3 * q[1]);
    geom::Loop loop;
    loop.outer = true;
    loop.coedges.push_back({geom::NurbsCurve2d(2, {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4}, P, {1, w, 1, w, 1, w, 1, w, 1}), -1, false});
    face.loops = {loop};
    const double area = trimmed_area(S, TrimRegion(face));
    // Error dominated by the tangent rows at the top and bottom (see trimmed_area).
    EXPECT_NEAR(area, M_PI * 0.09, 1e-4 * M_PI * 0.09);
}

TEST(MeasureDeviation, RejectsBadInput) {
    const geom::NurbsSurface S = geom::plane_patch({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0, 1, 0, 1);
    mesh::Mesh m = grid_mesh(S, 2, 2);
    m.face_ids[0] = 3;
    EXPECT_THROW(measure_deviation(model_of(S), m), geom::InvalidInput);
    DeviationOptions bad;
    bad.samples = 0;
    EXPECT_THROW(measure_deviation(model_of(S), grid_mesh(S, 2, 2), bad), geom::InvalidInput);
}

TEST(MeasureDeviation, ResultDoesNotDependOnThreads) {
    const geom::NurbsSurface S = geom::sphere_patch(kOrigin, kAxis, kRef, 1.0, 0.0, 1.0, 0.0, 1.0);
    const mesh::Mesh m = grid_mesh(S, 20, 20, 0.001);
    DeviationOptions one, four;
    one.threads = 1;
    four.threads = 4;
    const DeviationReport a = measure_deviation(model_of(S), m, one), b = measure_deviation(model_of(S), m, four);
    EXPECT_EQ(a.mesh_to_surface.max, b.mesh_to_surface.max);
    EXPECT_EQ(a.mesh_to_surface.mean, b.mesh_to_surface.mean);
    EXPECT_EQ(a.surface_to_mesh.mean, b.surface_to_mesh.mean);
    EXPECT_EQ(a.area_exact, b.area_exact);
}

}  // namespace
}  // namespace trimkit::tess
