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

}  // namespace
}  // namespace trimkit::tess
