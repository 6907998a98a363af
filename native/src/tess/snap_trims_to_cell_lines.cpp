#include "tess/snap_trims_to_cell_lines.h"

#include <algorithm>
#include <cmath>

namespace trimkit::tess {
namespace {

// The distinct values of a cell coordinate, ascending.
std::vector<double> lines(const CellGrid& grid, int d) {
    std::vector<double> out;
    out.reserve(2 * grid.cells.size());
    for (const Cell& c : grid.cells) {
        out.push_back(d == 0 ? c.u0 : c.v0);
        out.push_back(d == 0 ? c.u1 : c.v1);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

// x moved onto the nearest of `at` when it is within eps of it.
bool snap(double& x, const std::vector<double>& at, double eps) {
    const auto hi = std::lower_bound(at.begin(), at.end(), x);
    double best = INFINITY;
    if (hi != at.end()) best = *hi;
    if (hi != at.begin() && (best == INFINITY || x - *(hi - 1) < best - x)) best = *(hi - 1);
    if (!(std::abs(best - x) <= eps) || best == x) return false;
    x = best;
    return true;
}

int snap_to_lines(std::vector<TrimPolygon>& loops, const std::vector<double>& u_lines,
                  const std::vector<double>& v_lines, double eps) {
    int moved = 0;
    for (TrimPolygon& loop : loops)
        for (PolylinePoint& p : loop.points) {
            moved += snap(p.uv.x(), u_lines, eps) ? 1 : 0;
            moved += snap(p.uv.y(), v_lines, eps) ? 1 : 0;
        }
    return moved;
}

std::vector<double> distinct(std::vector<double> knots) {
    knots.erase(std::unique(knots.begin(), knots.end()), knots.end());
    return knots;
}

}  // namespace

int snap_trims_to_cell_lines(std::vector<TrimPolygon>& loops, const CellGrid& grid, double eps) {
    return snap_to_lines(loops, lines(grid, 0), lines(grid, 1), eps);
}

int snap_trims_to_knot_lines(std::vector<TrimPolygon>& loops, const geom::NurbsSurface& surface, double eps) {
    return snap_to_lines(loops, distinct(surface.knots_u()), distinct(surface.knots_v()), eps);
}

}  // namespace trimkit::tess
