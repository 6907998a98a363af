// Trim points a hair off a cell line go onto it (tess/snap_trims_to_cell_lines).
#include <gtest/gtest.h>

#include "geom/analytic_surfaces.h"
#include "tess/snap_trims_to_cell_lines.h"

namespace trimkit::tess {
namespace {

TrimPolygon polygon(const std::vector<Eigen::Vector2d>& uv) {
    TrimPolygon p;
    for (const Eigen::Vector2d& x : uv) p.points.push_back({x, Eigen::Vector3d(x.x(), x.y(), 7.0)});
    return p;
}

// Two cells [0, 1) x [0, 0.5) and [0, 1) x [0.5, 1): a trim along v = 0.5 with noise
// of 3e-10 either side lands on the line; a point 1e-6 off and the xyz stay.
TEST(SnapTrimsToCellLines, NoiseAboutALineGoesOntoItAndNothingElseMoves) {
    CellGrid grid;
    grid.cells = {{0, 1, 0, 0.5}, {0, 1, 0.5, 1}};
    std::vector<TrimPolygon> loops = {
        polygon({{0.1, 0.5 - 3e-10}, {0.4, 0.5 + 3e-10}, {0.7, 0.5 + 1e-6}, {0.9, 0.5}})};
    EXPECT_EQ(snap_trims_to_cell_lines(loops, grid, 1e-9), 2);
    const auto& p = loops[0].points;
    EXPECT_EQ(p[0].uv.y(), 0.5);
    EXPECT_EQ(p[1].uv.y(), 0.5);
    EXPECT_EQ(p[2].uv.y(), 0.5 + 1e-6);
    EXPECT_EQ(p[0].uv.x(), 0.1);
    EXPECT_EQ(p[1].xyz.y(), 0.5 + 3e-10);
}

// Each coordinate goes to its nearest line: a point near the corner (1, 0.5)
// snaps in both, one between two close lines to the nearer.
TEST(SnapTrimsToCellLines, NearestLineInEachCoordinate) {
    CellGrid grid;
    grid.cells = {{0, 1, 0, 0.5}, {1, 1 + 4e-9, 0, 0.5}, {0, 1, 0.5, 1}};
    std::vector<TrimPolygon> loops = {polygon({{1 + 1e-10, 0.5 - 1e-10}, {1 + 3e-9, 0.2}})};
    EXPECT_EQ(snap_trims_to_cell_lines(loops, grid, 2e-9), 3);
    EXPECT_EQ(loops[0].points[0].uv, Eigen::Vector2d(1, 0.5));
    EXPECT_EQ(loops[0].points[1].uv.x(), 1 + 4e-9);
}

// Knot lines: a cylinder's quarter-circle knots at pi/2 steps in u; a trim 2e-10 off
// u = pi goes onto it, one 1e-3 off does not.
TEST(SnapTrimsToKnotLines, NoiseAboutAKnotLineGoesOntoIt) {
    const geom::NurbsSurface cylinder = geom::cylinder_patch(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(),
                                                             Eigen::Vector3d::UnitX(), 5, 0, 2 * M_PI, 0, 10);
    std::vector<TrimPolygon> loops = {polygon({{M_PI + 2e-10, 3}, {M_PI - 1e-3, 4}})};
    EXPECT_EQ(snap_trims_to_knot_lines(loops, cylinder, 1e-9), 1);
    EXPECT_EQ(loops[0].points[0].uv.x(), M_PI);
    EXPECT_EQ(loops[0].points[1].uv.x(), M_PI - 1e-3);
}

}  // namespace
}  // namespace trimkit::tess
