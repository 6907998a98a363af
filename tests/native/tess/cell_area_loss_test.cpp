#include "tess/cell_area_loss.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geom/analytic_surfaces.h"

namespace trimkit::tess {
namespace {

// A strip of `n` quads, two triangles each, between the iso-lines v = v0 and v = v1
// at u = u0 .. u1 in n equal steps; vertices on S; the two long sides flagged as
// face boundary when `flag_sides`.
mesh::Mesh strip(const geom::NurbsSurface& S, double u0, double u1, double v0, double v1, int n, bool flag_sides) {
    mesh::Mesh m;
    for (int i = 0; i <= n; ++i)
        for (double v : {v0, v1}) {
            const Eigen::Vector2d uv(u0 + (u1 - u0) * i / n, v);
            m.uvs.push_back(uv);
            m.positions.push_back(S.evaluate(uv.x(), uv.y()));
        }
    for (int i = 0; i < n; ++i) {
        const int a = 2 * i, b = 2 * i + 2, c = 2 * i + 3, d = 2 * i + 1;
        m.triangles.push_back({a, b, c});
        m.triangles.push_back({a, c, d});
        if (flag_sides) {
            m.edges.push_back({a, b, mesh::kFaceBoundary});
            m.edges.push_back({d, c, mesh::kFaceBoundary});
        }
    }
    return m;
}

TEST(CellAreaLoss, CylinderStripLosesItsPolygonsPerimeterDeficit) {
    // Each quad is a flat rectangle of width 2 r sin(a/2) for the angle a it spans, on
    // a surface strip r a wide: the loss is h (r Theta - sum 2 r sin(a_i / 2)). The
    // chords along the circles bow off S radially, not into the face: no lens.
    const double r = 2.0, h = 3.0;
    const geom::NurbsSurface S = geom::cylinder_patch({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, r, 0.0, M_PI, 0.0, h);
    for (int n : {6, 12, 40}) {  // 30 degrees and less (chords within r / 30 of their arcs)
        const mesh::Mesh m = strip(S, 0.0, M_PI, 0.0, h, n, true);
        double flat = 0.0;
        for (int i = 0; i < n; ++i) {
            const Eigen::Vector3d p = m.positions[2 * i], q = m.positions[2 * i + 2];
            const double a = std::abs(std::atan2(q.y(), q.x()) - std::atan2(p.y(), p.x()));
            flat += 2.0 * r * std::sin(0.5 * a);
        }
        const double expected = h * (r * M_PI - flat);
        EXPECT_NEAR(cell_area_loss(S, m), expected, 1e-3 * expected) << n;
        EXPECT_NEAR(cell_area_loss(S, strip(S, 0.0, M_PI, 0.0, h, n, false)), expected, 1e-3 * expected) << n;
    }
}

TEST(CellAreaLoss, PlaneLosesNothing) {
    const geom::NurbsSurface S = geom::plane_patch({1, 2, 3}, {1, 0, 0.5}, {0, 1, 0}, 0.0, 4.0, 0.0, 2.0);
    EXPECT_NEAR(cell_area_loss(S, strip(S, 0.0, 4.0, 0.0, 2.0, 5, false)), 0.0, 1e-12);
}

TEST(CellAreaLoss, BoundaryLensBelongsToTheTrims) {
    // S(u, v) = (u^2, v, 0): a plane whose parameter speed grows along u. The (u,v)
    // triangle (0,0) (1,0) (1,1) spans the region v <= u, x = u^2: area 2/3 against
    // the flat triangle's 1/2. Its side (0,0)-(1,1) runs along x = y^2 on S: the lens
    // between it and its chord, 1/6, is the trims' loss when the side is a face
    // boundary, and what is left for the cells is the other 0.
    const geom::NurbsSurface S(2, 1, {0, 0, 0, 1, 1, 1}, {0, 0, 1, 1}, 3, 2,
                               {{0, 0, 0}, {0, 1, 0}, {0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}});
    mesh::Mesh m;
    m.uvs = {{0, 0}, {1, 0}, {1, 1}};
    for (const auto& uv : m.uvs) m.positions.push_back(S.evaluate(uv.x(), uv.y()));
    m.triangles = {{0, 1, 2}};
    EXPECT_NEAR(cell_area_loss(S, m), 1.0 / 6.0, 1e-12);
    m.edges.push_back({2, 0, mesh::kFaceBoundary});
    EXPECT_NEAR(cell_area_loss(S, m), 0.0, 1e-12);
}

}  // namespace
}  // namespace trimkit::tess
