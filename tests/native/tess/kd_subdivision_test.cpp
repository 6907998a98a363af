#include "tess/kd_subdivision.h"

#include <gtest/gtest.h>

#include "surface_test_support.h"
#include "tess/bezier_patch.h"
#include "tess/bilinear_error.h"

namespace trimkit::tess {
namespace {

double area(const Cell& c) { return (c.u1 - c.u0) * (c.v1 - c.v0); }

bool meets_loop(const Cell& c, const TrimPolygon& loop) {
    // Sampled along the loop's segments: enough for the test's coarse cells.
    for (size_t i = 0, n = loop.points.size(); i < n; ++i)
        for (int k = 0; k <= 50; ++k) {
            const Eigen::Vector2d p = loop.points[i].uv + (k / 50.0) * (loop.points[(i + 1) % n].uv - loop.points[i].uv);
            if (p.x() >= c.u0 && p.x() <= c.u1 && p.y() >= c.v0 && p.y() <= c.v1) return true;
        }
    return false;
}

// Trim-aware cells: cells that the loop meets hold the boundary tolerance, cells
// inside it the interior one, cells outside it are not subdivided; all tile the box.
TEST(KdSubdivision, TrimAwareTolerancesAndNoWorkOutsideTheLoops) {
    const geom::NurbsSurface S = test::bicubic_patch();
    const TrimPolygon loop = test::circle_loop(S, 0.5, 0.5, 0.3, 64);
    const Eigen::AlignedBox2d box(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1));
    const double interior = 4e-3, boundary = 1e-3;
    const CellGrid plain = kd_subdivision(S, box, boundary, ErrorMode::kGuaranteed);
    const CellGrid aware = kd_subdivision(S, box, interior, boundary, interior, {loop}, ErrorMode::kGuaranteed);
    EXPECT_LT(aware.cells.size(), plain.cells.size());
    double total = 0.0;
    const BezierPatch patch = bezier_patch(S);
    int outside = 0;
    for (const Cell& c : aware.cells) {
        total += area(c);
        const double bound = bilinear_error(restrict_patch(patch, c.u0, c.u1, c.v0, c.v1),
                                            ErrorMode::kGuaranteed, boundary).bound;
        const Eigen::Vector2d centre(0.5 * (c.u0 + c.u1), 0.5 * (c.v0 + c.v1));
        if (meets_loop(c, loop)) {
            EXPECT_LE(bound, interior * (1 + 1e-9));  // <= interior - offsets, >= boundary
        } else if ((centre - Eigen::Vector2d(0.5, 0.5)).norm() < 0.3) {
            EXPECT_LE(bound, interior * (1 + 1e-9));
        } else {
            ++outside;
        }
    }
    EXPECT_NEAR(total, 1.0, 1e-12);
    EXPECT_GT(outside, 0);
    // With no room for offsets (total = boundary), cells the loop meets hold the
    // boundary tolerance.
    const CellGrid tight = kd_subdivision(S, box, interior, boundary, boundary, {loop}, ErrorMode::kGuaranteed);
    for (const Cell& c : tight.cells)
        if (meets_loop(c, loop))
            EXPECT_LE(bilinear_error(restrict_patch(patch, c.u0, c.u1, c.v0, c.v1), ErrorMode::kGuaranteed,
                                     boundary).bound,
                      boundary * (1 + 1e-9));
}

using test::paraboloid;

bool crosses_knot_line(const Cell& c, int spans) {
    for (int k = 1; k < spans; ++k) {
        const double x = double(k) / spans;
        if ((c.u0 < x && x < c.u1) || (c.v0 < x && x < c.v1)) return true;
    }
    return false;
}

// Cells over several knot spans (block_error.h): on the paraboloid S_uu = S_vv = (0, 0, 2)
// and S_uv = 0, so a cell du x dv is within (du^2 + dv^2) / 4. With 8 spans of 1/8 and
// T = 0.02: a block of 2 x 2 spans (0.25 x 0.25) has 0.03125 > T, one span by two
// (0.125 x 0.25) has 0.0195 <= T, so the cells are 32 such blocks, where cells that stop
// at every knot line would be at least the 64 patches.
TEST(KdSubdivision, CellsCrossKnotLinesWhereTheirBoundAllows) {
    const int spans = 8;
    const geom::NurbsSurface S = paraboloid(spans);
    const double T = 0.02;
    const Eigen::AlignedBox2d box(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1));
    const CellGrid grid = kd_subdivision(S, box, T, ErrorMode::kGuaranteed);
    EXPECT_EQ(grid.cells.size(), 32u);
    double total = 0.0;
    for (const Cell& c : grid.cells) {
        total += area(c);
        EXPECT_TRUE(crosses_knot_line(c, spans)) << c.u0 << " " << c.v0;
        // The corner triangles against S at the same (u,v), sampled: within T.
        const Eigen::Vector3d A = S.evaluate(c.u0, c.v0), B = S.evaluate(c.u1, c.v0);
        const Eigen::Vector3d C = S.evaluate(c.u1, c.v1), D = S.evaluate(c.u0, c.v1);
        for (int i = 0; i <= 10; ++i)
            for (int j = 0; i + j <= 10; ++j) {
                const double s = i / 10.0, t = j / 10.0;  // in the triangle A B C and A C D
                const Eigen::Vector3d p1 = A + s * (B - A) + t * (C - A);
                const Eigen::Vector3d p2 = A + s * (C - A) + t * (D - A);
                EXPECT_LE((p1 - S.evaluate(p1.x(), p1.y())).norm(), T * (1 + 1e-12));
                EXPECT_LE((p2 - S.evaluate(p2.x(), p2.y())).norm(), T * (1 + 1e-12));
            }
    }
    EXPECT_NEAR(total, 1.0, 1e-12);
}

// A C^0 knot line (multiplicity = degree) is a crease of the parameterisation even where
// the surface is flat: no cell crosses it (Taylor's remainder does not hold across it).
TEST(KdSubdivision, NoCellCrossesAC0KnotLine) {
    const Eigen::AlignedBox2d box(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 1));
    const geom::NurbsSurface plane = paraboloid(4, true);
    EXPECT_EQ(kd_subdivision(plane, box, 1e-6, ErrorMode::kGuaranteed).cells.size(), 1u);
    const geom::NurbsSurface creased = plane.insert_knot_u(0.5);  // 0.5 twice: C^0 for degree 2
    const CellGrid grid = kd_subdivision(creased, box, 1e-6, ErrorMode::kGuaranteed);
    ASSERT_EQ(grid.cells.size(), 2u);
    for (const Cell& c : grid.cells) EXPECT_TRUE(c.u1 <= 0.5 || c.u0 >= 0.5) << c.u0 << " " << c.u1;
}

}  // namespace
}  // namespace trimkit::tess
