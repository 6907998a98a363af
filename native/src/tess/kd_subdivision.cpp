#include "tess/kd_subdivision.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>

#include "geom/error.h"
#include "tess/bezier_patch.h"
#include "tess/bilinear_error.h"
#include "tess/block_error.h"
#include "tess/derivative_bounds.h"
#include "tess/second_derivative_bound.h"

namespace trimkit::tess {
namespace {

using geom::format_value;

// A cell narrower than this fraction of the box is not split further: the
// parameters can no longer be told apart reliably (double has ~16 digits).
constexpr double kMinRelativeWidth = 1e-12;
// A patch's part in the box narrower than this share of the box, at the box's side,
// makes no cells of its own: its neighbour's cells are stretched over it.
constexpr double kSideSliver = 1e-6;

// The trim segments a kd-tree node meets, for trim-aware tolerances.
struct TrimSegments {
    std::vector<std::array<Eigen::Vector2d, 2>> segments;
    // Per segment: F >= sup |f''|, f(s) = S(a + s (b - a)); a crossing at s lies
    // within s (1 - s) F / 2 of S at its (u,v) (linear interpolation error). First
    // from the derivative bounds over the segment's loop's box; from its own box
    // (tighter, one sub-surface each) once a cell needs it (`precise`).
    std::vector<double> curvature;
    std::vector<char> precise;
    std::vector<int> next;  // per segment: the segment after it in its loop
    const geom::NurbsSurface* surface = nullptr;
    double tolerance = 0.0;           // cells no segment meets (inside the loops)
    double boundary_tolerance = 0.0;  // cells a segment meets, at least
    double total_tolerance = 0.0;     // cells a segment meets: bound + crossing offset
    double margin = 0.0;              // absolute, in (u,v)
    bool active = false;              // false: every cell uses `tolerance`
    const RevolutionShape* shape = nullptr;  // exact bound (revolution_error) if set
    mesh::Deadline* deadline = nullptr;      // checked per node and per segment test
};

// The cell's bound: revolution_error where it applies, else bilinear_error.
BilinearError cell_error(const TrimSegments& trims, const BezierPatch& patch, ErrorMode mode,
                         double tolerance) {
    if (trims.shape) {
        const BilinearError exact = revolution_error(*trims.shape, patch, tolerance);
        if (std::isfinite(exact.bound)) return exact;
    }
    return bilinear_error(patch, mode, tolerance);
}

// True if segment a b meets the closed rectangle grown by `margin` (Liang-Barsky);
// then [*lo, *hi] is the part of the segment inside.
bool meets(const std::array<Eigen::Vector2d, 2>& ab, double u0, double u1, double v0, double v1,
           double margin, double* lo_out = nullptr, double* hi_out = nullptr) {
    const Eigen::Vector2d a = ab[0], d = ab[1] - ab[0];
    double lo = 0.0, hi = 1.0;
    const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
    const double q[4] = {a.x() - (u0 - margin), (u1 + margin) - a.x(), a.y() - (v0 - margin),
                         (v1 + margin) - a.y()};
    for (int k = 0; k < 4; ++k) {
        if (p[k] == 0.0) {
            if (q[k] < 0.0) return false;
            continue;
        }
        const double r = q[k] / p[k];
        if (p[k] < 0.0) lo = std::max(lo, r);
        else hi = std::min(hi, r);
        if (lo > hi) return false;
    }
    if (lo_out) *lo_out = lo, *hi_out = hi;
    return true;
}

// [Yang] eq. 10 with c linear: |f''| <= M^uu Δu² + 2 M^uv |Δu Δv| + M^vv Δv², M the
// derivative bounds over a region holding the segment; infinite across a C^0 knot
// line (is_c1_inside).
double segment_curvature(const geom::NurbsSurface& S, const std::array<Eigen::Vector2d, 2>& ab,
                         const SurfaceDerivativeBounds& M) {
    Eigen::AlignedBox2d seg_box(ab[0]);
    seg_box.extend(ab[1]);
    if (!is_c1_inside(S, seg_box)) return std::numeric_limits<double>::infinity();
    const double du = std::abs(ab[1].x() - ab[0].x()), dv = std::abs(ab[1].y() - ab[0].y());
    return M.Muu * du * du + 2.0 * M.Muv * du * dv + M.Mvv * dv * dv;
}

// The largest offset from S of the node's crossings: where the segments meeting it
// enter or leave it (their points inside are trim points, on S). Offsets up to
// `harmless` do not change the cell's tolerance: coarse curvatures are refined only
// above it.
double crossing_offset(TrimSegments& trims, const std::vector<int>& segments, const Cell& r,
                       double harmless) {
    double worst = 0.0;
    for (int s : segments) {
        double lo = 0.0, hi = 1.0;
        if (!meets(trims.segments[s], r.u0, r.u1, r.v0, r.v1, trims.margin, &lo, &hi)) continue;
        double x = 0.0;
        if (lo > 0.0) x = std::max(x, 0.5 * lo * (1.0 - lo));
        if (hi < 1.0) x = std::max(x, 0.5 * hi * (1.0 - hi));
        if (x * trims.curvature[s] > harmless && !trims.precise[s]) {
            Eigen::AlignedBox2d seg_box(trims.segments[s][0]);
            seg_box.extend(trims.segments[s][1]);
            trims.curvature[s] = std::min(
                trims.curvature[s], segment_curvature(*trims.surface, trims.segments[s],
                                                      surface_derivative_bounds(*trims.surface, seg_box)));
            trims.precise[s] = 1;
        }
        worst = std::max(worst, x * trims.curvature[s]);
    }
    return worst;
}

// Even-odd test of (u, v) against all segments, half-open in v as in trim_cells.
bool inside_loops(const TrimSegments& trims, double u, double v) {
    bool in = false;
    for (const auto& [a, b] : trims.segments) {
        mesh::check_deadline(trims.deadline, "kd subdivision");
        if ((a.y() > v) != (b.y() > v)) {
            const double x = a.x() + (v - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
            if (x > u) in = !in;
        }
    }
    return in;
}

// A split line through a trim vertex crosses the trim there, at a point on S, instead
// of on a chord: no crossing vertex is added to the trim, nor (by close_t_junctions) to
// the face beside it. On a cylinder between two circles approximated alike, a split
// along a ruling at a vertex of one meets a vertex of the other too, and the cells add
// no boundary point at all (xr1-tc-nut.stp at 1e-3: 67 -> 45 points on each circle of
// the plate's hole, 544 -> 384 triangles). So such a split moves to the trim vertex
// nearest to it within kSnapWindow of the cell's width and at least kSnapKeep of the
// width from its sides; the halves are subdivided further as before, so every leaf
// keeps its bound. Only where the trim crosses the line at the vertex (its neighbours
// on the two sides by more than kSnapSide of the width) and every segment that could
// cross the line in the window runs square to it (within atan(1 / kSnapSteep)), as a
// cylinder's circles do: a trim touching the line at the vertex or running along it
// left non-manifold cells, and a line moved beside a hole's points folded triangles
// along a cell side (a bicubic with a hole, TessellateFace tests).
constexpr double kSnapWindow = 0.25, kSnapKeep = 0.2, kSnapSide = 1e-6, kSnapSteep = 1e6;
// Corners of a cylinder's patch lie this close (relative) to one distance from the axis.
constexpr double kCylinderRelative = 1e-9;

// The split (local, in (0, 1)) and, when it moved to a vertex, the vertex's own
// coordinate, which the halves then meet at exactly (the local parameter would give it
// only up to rounding, and a trim vertex a hair off a cell line leaves slivers).
struct Split {
    double local = 0.5;
    std::optional<double> at;
};

// True when `patch` is a piece of a cylinder (a surface of revolution whose meridian is
// a line parallel to its axis: its four corners equally far from the axis) and `in_u`
// splits it along a ruling. Not cones: their whole-ruling cells' long triangles were
// re-triangulated in 3D and stood across the surface (a frustum with a hole,
// OcctModels.FrustumCellsAlongWholeRulingsDoNotFold).
bool splits_cylinder_along_ruling(const RevolutionShape* shape, const BezierPatch& patch, bool in_u) {
    if (!shape || shape->circle_meridian || in_u != (shape->angle_dir == 0)) return false;
    double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
    for (int i : {0, patch.p})
        for (int j : {0, patch.q}) {
            const Eigen::Vector4d& h = patch.point(i, j);
            if (!(h.w() > 0.0)) return false;
            const double rho = shape->meridian(h.head<3>() / h.w()).x();
            lo = std::min(lo, rho), hi = std::max(hi, rho);
        }
    return hi - lo <= kCylinderRelative * std::max(hi, 1.0);
}

// Coordinates along the split direction (across the split line) and across it.
struct SplitAxes {
    bool in_u;
    double along(const Eigen::Vector2d& x) const { return in_u ? x.x() : x.y(); }
    double across(const Eigen::Vector2d& x) const { return in_u ? x.y() : x.x(); }
    bool square(const Eigen::Vector2d& d) const { return std::abs(along(d)) >= kSnapSteep * std::abs(across(d)); }
};

// True when every segment that reaches into [lo, hi] along the axes runs square to them.
bool segments_square_in(const TrimSegments& trims, const std::vector<int>& segments, const SplitAxes& axes,
                        double lo, double hi) {
    for (int s : segments) {
        const Eigen::Vector2d &p = trims.segments[s][0], &q = trims.segments[s][1];
        if (std::max(axes.along(p), axes.along(q)) < lo || std::min(axes.along(p), axes.along(q)) > hi) continue;
        if (!axes.square(q - p)) return false;
    }
    return true;
}

Split snap_split_to_trim_vertex(const TrimSegments& trims, const std::vector<int>& segments,
                                const BezierPatch& patch, bool in_u, double split) {
    Split best{split, std::nullopt};
    if (!splits_cylinder_along_ruling(trims.shape, patch, in_u)) return best;
    const SplitAxes axes{in_u};
    const double a = in_u ? patch.u0 : patch.v0, b = in_u ? patch.u1 : patch.v1;
    const double c = in_u ? patch.v0 : patch.u0, d = in_u ? patch.v1 : patch.u1;
    const double width = b - a, ideal = a + split * width;
    const double lo = std::max(ideal - kSnapWindow * width, a + kSnapKeep * width);
    const double hi = std::min(ideal + kSnapWindow * width, b - kSnapKeep * width);
    if (!(lo < hi) || !segments_square_in(trims, segments, axes, lo, hi)) return best;
    double best_distance = std::numeric_limits<double>::infinity();
    for (int s : segments) {
        // The segment's end vertex x, between its start p and the next segment's end q.
        const Eigen::Vector2d& x = trims.segments[s][1];
        const Eigen::Vector2d& p = trims.segments[s][0];
        const Eigen::Vector2d& q = trims.segments[trims.next[s]][1];
        const double along = axes.along(x), across = axes.across(x);
        // A trim along the cell's side counts (it lies within the margin).
        if (along < lo || along > hi || across < c - trims.margin || across > d + trims.margin) continue;
        const double before = axes.along(p) - along, after = axes.along(q) - along, side = kSnapSide * width;
        if (!((before < -side && after > side) || (before > side && after < -side))) continue;
        if (!axes.square(x - p) || !axes.square(q - x) || std::abs(along - ideal) >= best_distance) continue;
        best_distance = std::abs(along - ideal);
        best = Split{(along - a) / width, along};
    }
    return best;
}

struct Node {
    BezierPatch patch;
    std::vector<int> segments;  // trim segments meeting the node (trims.active)
    // The parent's second-derivative bound restricted to this node (local parameters):
    // a node it already keeps within tolerance is a leaf without a bound of its own.
    std::optional<SecondDerivativeBound> inherited;
};

// The trim segments of `from` that meet the (stretched) rectangle r, appended to out.
void segments_meeting(const TrimSegments& trims, const Cell& r, const std::vector<int>& from,
                      std::vector<int>& out) {
    for (int s : from) {
        mesh::check_deadline(trims.deadline, "kd subdivision");
        if (meets(trims.segments[s], r.u0, r.u1, r.v0, r.v1, trims.margin)) out.push_back(s);
    }
}

std::vector<int> all_segments(const TrimSegments& trims) {
    std::vector<int> all(trims.segments.size());
    for (size_t s = 0; s < all.size(); ++s) all[s] = static_cast<int>(s);
    return all;
}

// The bound a node's cell must meet (kd_subdivision.h: trim-aware tolerances), or
// empty when no trim meets it and it lies outside the loops: a leaf as it is, which
// trim_cells drops. `r`: the node's stretched rectangle.
std::optional<double> node_tolerance(TrimSegments& trims, const std::vector<int>& segments, const Cell& r) {
    if (!trims.active) return trims.tolerance;
    if (segments.empty()) {
        if (!inside_loops(trims, 0.5 * (r.u0 + r.u1), 0.5 * (r.v0 + r.v1))) return std::nullopt;
        return trims.tolerance;
    }
    const double harmless = trims.total_tolerance - trims.tolerance;
    return std::min(trims.tolerance, std::max(trims.boundary_tolerance,
                                              trims.total_tolerance - crossing_offset(trims, segments, r, harmless)));
}

void add_leaf(const Cell& cell, double tolerance, std::vector<Cell>& leaves) {
    leaves.push_back(cell);
    if (leaves.size() > kMaxCells)
        throw geom::NumericalFailure("kd_subdivision: more than " + std::to_string(kMaxCells) +
                                     " cells needed for tolerance " + format_value(tolerance));
}

// Splits `root` (a piece of one Bezier patch, with the trim segments that meet it) at
// the point of largest bilinear error until its cells are within their bounds.
// `stretch`: the (u,v) rectangle a cell covers after kd_subdivision stretches the
// domain's sides to the box's.
template <class Stretch>
void subdivide(Node root, TrimSegments& trims, const Stretch& stretch, ErrorMode mode, double min_du,
               double min_dv, std::vector<Cell>& leaves) {
    // Explicit stack: deep kd-trees on fine tolerances must not overflow the call stack.
    std::vector<Node> stack;
    stack.push_back(std::move(root));
    while (!stack.empty()) {
        mesh::check_deadline(trims.deadline, "kd subdivision");
        Node node = std::move(stack.back());
        stack.pop_back();
        const BezierPatch& current = node.patch;
        const Cell cell{current.u0, current.u1, current.v0, current.v1};
        const std::optional<double> tolerance = node_tolerance(trims, node.segments, stretch(cell));
        if (!tolerance) {
            leaves.push_back(cell);
            continue;
        }
        if (node.inherited && node.inherited->error() <= *tolerance) {
            add_leaf(cell, *tolerance, leaves);
            continue;
        }
        const BilinearError error = cell_error(trims, current, mode, *tolerance);
        if (!std::isfinite(error.bound))
            throw geom::NumericalFailure(
                "kd_subdivision: non-finite bilinear error on cell [" + format_value(current.u0) +
                ", " + format_value(current.u1) + "] x [" + format_value(current.v0) + ", " +
                format_value(current.v1) + "]");
        const bool can_u = current.u1 - current.u0 > min_du;
        const bool can_v = current.v1 - current.v0 > min_dv;
        if (error.bound <= *tolerance || (!can_u && !can_v)) {
            add_leaf(cell, *tolerance, leaves);
            continue;
        }
        bool in_u = error.split_in_u;
        if (in_u && !can_u) in_u = false;
        if (!in_u && !can_v) in_u = true;
        Split split{in_u == error.split_in_u ? error.split : 0.5, std::nullopt};
        if (trims.active && !node.segments.empty())
            split = snap_split_to_trim_vertex(trims, node.segments, current, in_u, split.local);
        auto halves = in_u ? split_u(current, split.local) : split_v(current, split.local);
        if (split.at && in_u) halves.first.u1 = halves.second.u0 = *split.at;
        if (split.at && !in_u) halves.first.v1 = halves.second.v0 = *split.at;
        Node first, second;
        first.patch = std::move(halves.first);
        second.patch = std::move(halves.second);
        if (error.derivatives)
            for (Node* child : {&first, &second})
                child->inherited = restricted_bound(*error.derivatives,
                                                    (child->patch.u1 - child->patch.u0) / (current.u1 - current.u0),
                                                    (child->patch.v1 - child->patch.v0) / (current.v1 - current.v0));
        if (trims.active) {
            segments_meeting(trims, stretch(Cell{first.patch.u0, first.patch.u1, first.patch.v0, first.patch.v1}),
                             node.segments, first.segments);
            segments_meeting(trims, stretch(Cell{second.patch.u0, second.patch.u1, second.patch.v0, second.patch.v1}),
                             node.segments, second.segments);
        }
        stack.push_back(std::move(second));
        stack.push_back(std::move(first));
    }
}

// The parts of the surface's Bezier patches inside the box, as a grid: part(iu, iv)
// spans [u[iu], u[iu + 1]] x [v[iv], v[iv + 1]].
struct Part {
    const geom::NurbsSurface* bezier;
    double u0, u1, v0, v1;
};
struct PartGrid {
    std::vector<double> u, v;  // the parts' sides, ascending
    std::vector<int> index;    // part per (iu, iv), iu * (v.size() - 1) + iv
    // The part whose span holds the rectangle c (which crosses no side).
    int holding(const Cell& c) const {
        const auto iu = std::upper_bound(u.begin(), u.end(), c.u0) - u.begin() - 1;
        const auto iv = std::upper_bound(v.begin(), v.end(), c.v0) - v.begin() - 1;
        return index[iu * (v.size() - 1) + iv];
    }
};

// The grid, or empty when the parts do not tile one (each grid cell one part).
std::optional<PartGrid> part_grid(const std::vector<Part>& parts) {
    PartGrid g;
    for (const Part& p : parts) g.u.insert(g.u.end(), {p.u0, p.u1}), g.v.insert(g.v.end(), {p.v0, p.v1});
    for (auto* x : {&g.u, &g.v}) {
        std::sort(x->begin(), x->end());
        x->erase(std::unique(x->begin(), x->end()), x->end());
    }
    if (g.u.size() < 2 || g.v.size() < 2 || (g.u.size() - 1) * (g.v.size() - 1) != parts.size()) return std::nullopt;
    g.index.assign(parts.size(), -1);
    for (size_t k = 0; k < parts.size(); ++k) {
        const auto iu = std::lower_bound(g.u.begin(), g.u.end(), parts[k].u0) - g.u.begin();
        const auto iv = std::lower_bound(g.v.begin(), g.v.end(), parts[k].v0) - g.v.begin();
        int& slot = g.index[iu * (g.v.size() - 1) + iv];
        if (slot >= 0 || g.u[iu + 1] != parts[k].u1 || g.v[iv + 1] != parts[k].v1) return std::nullopt;
        slot = static_cast<int>(k);
    }
    return g;
}

// The sides of `sides` strictly inside (lo, hi): [first, last) indices.
std::pair<long, long> sides_inside(const std::vector<double>& sides, double lo, double hi) {
    return {std::upper_bound(sides.begin(), sides.end(), lo) - sides.begin(),
            std::lower_bound(sides.begin(), sides.end(), hi) - sides.begin()};
}

// Cells over several knot spans (block_error.h): from the whole grid of parts, a block
// within its bound is one cell; one that is not splits at its middle knot line across
// the direction whose term is larger (at its middle where no knot line crosses that
// way); a block within one span in both directions is one Bezier patch's piece, which
// `subdivide` takes on. Not for surfaces of revolution: their exact bound is per patch.
template <class Stretch>
void subdivide_blocks(const geom::NurbsSurface& surface, const std::vector<Part>& parts, const PartGrid& grid,
                      TrimSegments& trims, const Stretch& stretch, ErrorMode mode, double min_du, double min_dv,
                      std::vector<Cell>& leaves) {
    struct Block {
        Cell cell;
        std::vector<int> segments;
    };
    // Per part, its second-derivative bound in the surface's parameters; a block's is
    // the largest over the parts it overlaps.
    std::vector<BezierPatch> part_patches(parts.size());
    std::vector<SecondDerivativeBound> part_bounds(parts.size());
    for (size_t k = 0; k < parts.size(); ++k) {
        const Part& p = parts[k];
        part_patches[k] = restrict_patch(bezier_patch(*p.bezier), p.u0, p.u1, p.v0, p.v1);
        part_bounds[k] = in_surface_parameters(second_derivative_bound(part_patches[k]), p.u1 - p.u0, p.v1 - p.v0);
    }
    const auto block_bound = [&](const Cell& c) {
        const long nv = static_cast<long>(grid.v.size()) - 1;
        const long iu0 = std::upper_bound(grid.u.begin(), grid.u.end(), c.u0) - grid.u.begin() - 1;
        const long iu1 = std::lower_bound(grid.u.begin(), grid.u.end(), c.u1) - grid.u.begin();
        const long iv0 = std::upper_bound(grid.v.begin(), grid.v.end(), c.v0) - grid.v.begin() - 1;
        const long iv1 = std::lower_bound(grid.v.begin(), grid.v.end(), c.v1) - grid.v.begin();
        SecondDerivativeBound M;
        for (long iu = iu0; iu < iu1; ++iu)
            for (long iv = iv0; iv < iv1; ++iv) {
                const SecondDerivativeBound& m = part_bounds[grid.index[iu * nv + iv]];
                M = {std::max(M.M_uu, m.M_uu), std::max(M.M_uv, m.M_uv), std::max(M.M_vv, m.M_vv)};
            }
        return M;
    };
    std::vector<Block> stack(1);
    stack[0].cell = Cell{grid.u.front(), grid.u.back(), grid.v.front(), grid.v.back()};
    if (trims.active) segments_meeting(trims, stretch(stack[0].cell), all_segments(trims), stack[0].segments);
    while (!stack.empty()) {
        mesh::check_deadline(trims.deadline, "kd subdivision");
        Block block = std::move(stack.back());
        stack.pop_back();
        const Cell c = block.cell;
        const auto [u_first, u_last] = sides_inside(grid.u, c.u0, c.u1);
        const auto [v_first, v_last] = sides_inside(grid.v, c.v0, c.v1);
        if (u_first == u_last && v_first == v_last) {
            Node node{restrict_patch(part_patches[grid.holding(c)], c.u0, c.u1, c.v0, c.v1), std::move(block.segments)};
            subdivide(std::move(node), trims, stretch, mode, min_du, min_dv, leaves);
            continue;
        }
        const std::optional<double> tolerance = node_tolerance(trims, block.segments, stretch(c));
        if (!tolerance) {
            leaves.push_back(c);
            continue;
        }
        const bool c1 = is_c1_inside(surface, Eigen::AlignedBox2d(Eigen::Vector2d(c.u0, c.v0), Eigen::Vector2d(c.u1, c.v1)));
        const BlockError error = c1 ? block_error(block_bound(c), c.u1 - c.u0, c.v1 - c.v0) : BlockError{};
        if (c1 && error.bound <= *tolerance) {
            add_leaf(c, *tolerance, leaves);
            continue;
        }
        bool in_u = c1 && std::isfinite(error.bound) ? error.u_term >= error.v_term : u_last - u_first >= v_last - v_first;
        if (in_u ? (c.u1 - c.u0 <= min_du) : (c.v1 - c.v0 <= min_dv)) in_u = !in_u;
        const auto [first, last] = in_u ? std::make_pair(u_first, u_last) : std::make_pair(v_first, v_last);
        const std::vector<double>& sides = in_u ? grid.u : grid.v;
        const double at = first < last ? sides[(first + last) / 2] : in_u ? 0.5 * (c.u0 + c.u1) : 0.5 * (c.v0 + c.v1);
        Block halves[2] = {{c, {}}, {c, {}}};
        (in_u ? halves[0].cell.u1 : halves[0].cell.v1) = at;
        (in_u ? halves[1].cell.u0 : halves[1].cell.v0) = at;
        for (Block& half : halves)
            if (trims.active) segments_meeting(trims, stretch(half.cell), block.segments, half.segments);
        stack.push_back(std::move(halves[1]));
        stack.push_back(std::move(halves[0]));
    }
}

}  // namespace

namespace {

CellGrid subdivide_box(const geom::NurbsSurface& surface, const Eigen::AlignedBox2d& box,
                       TrimSegments& trims, ErrorMode mode) {
    if (box.isEmpty() || !box.min().allFinite() || !box.max().allFinite() ||
        !(box.max().x() > box.min().x()) || !(box.max().y() > box.min().y()))
        throw geom::InvalidInput("kd_subdivision: (u,v) box must be finite and non-empty");
    for (double t : {trims.tolerance, trims.boundary_tolerance, trims.total_tolerance})
        if (!(t > 0.0) || !std::isfinite(t))
            throw geom::InvalidInput("kd_subdivision: tolerance = " + format_value(t) +
                                     "; expected a finite value > 0");
    const double bu0 = box.min().x(), bu1 = box.max().x(), bv0 = box.min().y(), bv1 = box.max().y();
    const double min_du = kMinRelativeWidth * (bu1 - bu0);
    const double min_dv = kMinRelativeWidth * (bv1 - bv0);
    trims.margin = kTrimMeetMargin * box.sizes().maxCoeff();
    // The patches' parts in the box, without slivers at the box's sides: a knot line
    // inside the box's margin beyond the loops (a surface extended past its seam, whose
    // knot 2pi lies 1e-9 inside the box) would give a row of cells thinner than the
    // margin, where a trim along the line makes triangles flat in (u,v) that stand
    // across the surface in 3D (torus_hole_on_seams_brep.igs: area +0.44 %).
    const double sliver_u = kSideSliver * (bu1 - bu0), sliver_v = kSideSliver * (bv1 - bv0);
    const std::vector<geom::NurbsSurface> beziers = surface.bezier_patches();
    std::vector<Part> parts;
    double su0 = bu1, su1 = bu0, sv0 = bv1, sv1 = bv0;  // the kept parts' extent
    for (const geom::NurbsSurface& bezier : beziers) {
        const auto [pu0, pu1] = bezier.domain_u();
        const auto [pv0, pv1] = bezier.domain_v();
        const Part p{&bezier, std::max(pu0, bu0), std::min(pu1, bu1), std::max(pv0, bv0), std::min(pv1, bv1)};
        if (!(p.u1 > p.u0) || !(p.v1 > p.v0)) continue;
        const bool side_sliver = (p.u1 - p.u0 < sliver_u && (p.u0 == bu0 || p.u1 == bu1)) ||
                                 (p.v1 - p.v0 < sliver_v && (p.v0 == bv0 || p.v1 == bv1));
        if (side_sliver) continue;
        parts.push_back(p);
        su0 = std::min(su0, p.u0), su1 = std::max(su1, p.u1);
        sv0 = std::min(sv0, p.v0), sv1 = std::max(sv1, p.v1);
    }
    // Cells on the kept parts' sides (the domain's sides, or a sliver's line) reach the
    // box's sides (trim points outside the domain; evaluation clamps to it there).
    const auto stretch = [&](Cell c) {
        if (c.u0 == su0) c.u0 = std::min(c.u0, bu0);
        if (c.u1 == su1) c.u1 = std::max(c.u1, bu1);
        if (c.v0 == sv0) c.v0 = std::min(c.v0, bv0);
        if (c.v1 == sv1) c.v1 = std::max(c.v1, bv1);
        return c;
    };

    CellGrid grid;
    grid.box = box;
    const std::optional<PartGrid> blocks =
        trims.shape || parts.size() < 2 ? std::nullopt : part_grid(parts);
    if (blocks) {
        subdivide_blocks(surface, parts, *blocks, trims, stretch, mode, min_du, min_dv, grid.cells);
    } else {
        for (const Part& p : parts) {
            Node node{restrict_patch(bezier_patch(*p.bezier), p.u0, p.u1, p.v0, p.v1), {}};
            if (trims.active)
                segments_meeting(trims, stretch(Cell{p.u0, p.u1, p.v0, p.v1}), all_segments(trims), node.segments);
            subdivide(std::move(node), trims, stretch, mode, min_du, min_dv, grid.cells);
        }
    }
    if (grid.cells.empty())
        throw geom::InvalidInput("kd_subdivision: (u,v) box [" + format_value(bu0) + ", " +
                                 format_value(bu1) + "] x [" + format_value(bv0) + ", " +
                                 format_value(bv1) + "] misses the surface's domain");
    for (Cell& c : grid.cells) c = stretch(c);
    grid.boundary = cell_boundaries(grid.cells);
    return grid;
}

}  // namespace

CellGrid kd_subdivision(const geom::NurbsSurface& surface, const Eigen::AlignedBox2d& box,
                        double tolerance, ErrorMode mode, const RevolutionShape* shape) {
    TrimSegments trims;
    trims.tolerance = trims.boundary_tolerance = trims.total_tolerance = tolerance;
    trims.shape = shape;
    return subdivide_box(surface, box, trims, mode);
}

CellGrid kd_subdivision(const geom::NurbsSurface& surface, const Eigen::AlignedBox2d& box,
                        double tolerance, double boundary_tolerance, double total_tolerance,
                        const std::vector<TrimPolygon>& loops, ErrorMode mode,
                        const RevolutionShape* shape, mesh::Deadline* deadline) {
    TrimSegments trims;
    trims.shape = shape;
    trims.deadline = deadline;
    trims.tolerance = tolerance;
    trims.boundary_tolerance = boundary_tolerance;
    trims.total_tolerance = total_tolerance;
    trims.surface = &surface;
    for (const TrimPolygon& loop : loops) {
        Eigen::AlignedBox2d loop_box;
        for (const PolylinePoint& p : loop.points) loop_box.extend(p.uv);
        if (loop.points.size() < 2) continue;
        const SurfaceDerivativeBounds M = surface_derivative_bounds(surface, loop_box);
        for (size_t i = 0, n = loop.points.size(); i < n; ++i) {
            trims.segments.push_back({loop.points[i].uv, loop.points[(i + 1) % n].uv});
            trims.curvature.push_back(segment_curvature(surface, trims.segments.back(), M));
            trims.precise.push_back(0);
            trims.next.push_back(static_cast<int>(trims.segments.size() - i + (i + 1) % n - 1));
        }
    }
    trims.active = !trims.segments.empty();
    return subdivide_box(surface, box, trims, mode);
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
