#include "tess/kd_subdivision.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "geom/error.h"
#include "tess/bezier_patch.h"
#include "tess/bilinear_error.h"

namespace trimkit::tess {
namespace {

using geom::format_value;

// A cell narrower than this fraction of the box is not split further: the
// parameters can no longer be told apart reliably (double has ~16 digits).
constexpr double kMinRelativeWidth = 1e-12;

void subdivide(const BezierPatch& patch, double tolerance, ErrorMode mode, double min_du,
               double min_dv, std::vector<Cell>& leaves) {
    // Explicit stack: deep kd-trees on fine tolerances must not overflow the call stack.
    std::vector<BezierPatch> stack{patch};
    while (!stack.empty()) {
        BezierPatch current = std::move(stack.back());
        stack.pop_back();
        const BilinearError error = bilinear_error(current, mode, tolerance);
        if (!std::isfinite(error.bound))
            throw geom::NumericalFailure(
                "kd_subdivision: non-finite bilinear error on cell [" + format_value(current.u0) +
                ", " + format_value(current.u1) + "] x [" + format_value(current.v0) + ", " +
                format_value(current.v1) + "]");
        const bool can_u = current.u1 - current.u0 > min_du;
        const bool can_v = current.v1 - current.v0 > min_dv;
        if (error.bound <= tolerance || (!can_u && !can_v)) {
            leaves.push_back({current.u0, current.u1, current.v0, current.v1});
            if (leaves.size() > kMaxCells)
                throw geom::NumericalFailure("kd_subdivision: more than " +
                                             std::to_string(kMaxCells) +
                                             " cells needed for tolerance " +
                                             format_value(tolerance));
            continue;
        }
        bool in_u = error.split_in_u;
        if (in_u && !can_u) in_u = false;
        if (!in_u && !can_v) in_u = true;
        const double split = in_u == error.split_in_u ? error.split : 0.5;
        auto halves = in_u ? split_u(current, split) : split_v(current, split);
        stack.push_back(std::move(halves.second));
        stack.push_back(std::move(halves.first));
    }
}

}  // namespace

CellGrid kd_subdivision(const geom::NurbsSurface& surface, const Eigen::AlignedBox2d& box,
                        double tolerance, ErrorMode mode) {
    if (box.isEmpty() || !box.min().allFinite() || !box.max().allFinite() ||
        !(box.max().x() > box.min().x()) || !(box.max().y() > box.min().y()))
        throw geom::InvalidInput("kd_subdivision: (u,v) box must be finite and non-empty");
    if (!(tolerance > 0.0) || !std::isfinite(tolerance))
        throw geom::InvalidInput("kd_subdivision: tolerance = " + format_value(tolerance) +
                                 "; expected a finite value > 0");
    const auto [du0, du1] = surface.domain_u();
    const auto [dv0, dv1] = surface.domain_v();
    const double bu0 = box.min().x(), bu1 = box.max().x(), bv0 = box.min().y(), bv1 = box.max().y();
    const double min_du = kMinRelativeWidth * (bu1 - bu0);
    const double min_dv = kMinRelativeWidth * (bv1 - bv0);

    CellGrid grid;
    grid.box = box;
    for (const geom::NurbsSurface& bezier : surface.bezier_patches()) {
        const auto [pu0, pu1] = bezier.domain_u();
        const auto [pv0, pv1] = bezier.domain_v();
        const double u0 = std::max(pu0, bu0), u1 = std::min(pu1, bu1);
        const double v0 = std::max(pv0, bv0), v1 = std::min(pv1, bv1);
        if (!(u1 > u0) || !(v1 > v0)) continue;
        const BezierPatch patch = restrict_patch(bezier_patch(bezier), u0, u1, v0, v1);
        subdivide(patch, tolerance, mode, min_du, min_dv, grid.cells);
    }
    if (grid.cells.empty())
        throw geom::InvalidInput("kd_subdivision: (u,v) box [" + format_value(bu0) + ", " +
                                 format_value(bu1) + "] x [" + format_value(bv0) + ", " +
                                 format_value(bv1) + "] misses the surface's domain");
    // Stretch cells on the domain's sides to the box's sides (trim points outside the
    // domain; evaluation clamps to the domain there).
    for (Cell& c : grid.cells) {
        if (c.u0 == std::max(du0, bu0)) c.u0 = std::min(c.u0, bu0);
        if (c.u1 == std::min(du1, bu1)) c.u1 = std::max(c.u1, bu1);
        if (c.v0 == std::max(dv0, bv0)) c.v0 = std::min(c.v0, bv0);
        if (c.v1 == std::min(dv1, bv1)) c.v1 = std::max(c.v1, bv1);
    }
    grid.boundary = cell_boundaries(grid.cells);
    return grid;
}

std::vector<std::vector<Eigen::Vector2d>> cell_boundaries(const std::vector<Cell>& cells) {
    // Corners of all cells, by the vertical (constant u) and horizontal lines they lie on.
    // Split values are shared bit for bit by neighbouring cells, so exact keys work.
    std::map<double, std::vector<double>> on_u, on_v;
    for (const Cell& c : cells) {
        for (double u : {c.u0, c.u1}) {
            auto& list = on_u[u];
            list.push_back(c.v0);
            list.push_back(c.v1);
        }
        for (double v : {c.v0, c.v1}) {
            auto& list = on_v[v];
            list.push_back(c.u0);
            list.push_back(c.u1);
        }
    }
    for (auto* lines : {&on_u, &on_v})
        for (auto& [key, list] : *lines) {
            std::sort(list.begin(), list.end());
            list.erase(std::unique(list.begin(), list.end()), list.end());
        }
    // Values strictly inside (a, b) on a line, ascending.
    auto inside = [](const std::vector<double>& list, double a, double b, auto&& emit) {
        for (auto it = std::upper_bound(list.begin(), list.end(), a); it != list.end() && *it < b;
             ++it)
            emit(*it);
    };
    std::vector<std::vector<Eigen::Vector2d>> boundary(cells.size());
    std::vector<double> buffer;
    for (size_t index = 0; index < cells.size(); ++index) {
        const Cell& c = cells[index];
        auto& out = boundary[index];
        out.emplace_back(c.u0, c.v0);
        inside(on_v[c.v0], c.u0, c.u1, [&](double u) { out.emplace_back(u, c.v0); });
        out.emplace_back(c.u1, c.v0);
        inside(on_u[c.u1], c.v0, c.v1, [&](double v) { out.emplace_back(c.u1, v); });
        out.emplace_back(c.u1, c.v1);
        buffer.clear();
        inside(on_v[c.v1], c.u0, c.u1, [&](double u) { buffer.push_back(u); });
        for (auto it = buffer.rbegin(); it != buffer.rend(); ++it) out.emplace_back(*it, c.v1);
        out.emplace_back(c.u0, c.v1);
        buffer.clear();
        inside(on_u[c.u0], c.v0, c.v1, [&](double v) { buffer.push_back(v); });
        for (auto it = buffer.rbegin(); it != buffer.rend(); ++it) out.emplace_back(c.u0, *it);
    }
    return boundary;
}

}  // namespace trimkit::tess
