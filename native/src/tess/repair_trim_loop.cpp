#include "tess/repair_trim_loop.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>
#include <utility>

#include <Eigen/Geometry>

#include "geom/segment_distance.h"

#include "mesh/grid_cell.h"
#include "mesh/triangulate_polygon.h"
#include "geom/clamped_int.h"

namespace trimkit::tess {

using mesh::GridCell;
using mesh::GridCellHash;

namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() * b.y() - a.y() * b.x();
}

PolylinePoint lerp(const PolylinePoint& a, const PolylinePoint& b, double s) {
    PolylinePoint p;
    p.uv = (1.0 - s) * a.uv + s * b.uv;
    p.xyz = (1.0 - s) * a.xyz + s * b.xyz;
    p.t = (1.0 - s) * a.t + s * b.t;
    return p;
}

// Consecutive points within snap merged (the earlier kept), closing duplicate removed.
std::vector<PolylinePoint> merge_close(const std::vector<PolylinePoint>& in, double snap) {
    std::vector<PolylinePoint> out;
    for (const PolylinePoint& p : in)
        if (out.empty() || (p.uv - out.back().uv).norm() > snap) out.push_back(p);
    while (out.size() > 1 && (out.back().uv - out.front().uv).norm() <= snap) out.pop_back();
    return out;
}

double perimeter(const std::vector<PolylinePoint>& P) {
    double L = 0.0;
    for (size_t i = 0; i < P.size(); ++i) L += (P[(i + 1) % P.size()].uv - P[i].uv).norm();
    return L;
}

// Width of a piece on the surface: twice its area over its perimeter. The area sums
// the piece's (u,v) triangles times the area element |S_u x S_v| at their centroids
// (triangles spanned by the xyz would not do: points along a curved 3D curve span
// area however thin the piece).
double width_on_surface(const std::vector<PolylinePoint>& P, const geom::NurbsSurface& surface,
                        mesh::Deadline* deadline) {
    std::vector<Eigen::Vector2d> uv;
    std::vector<int> ring;
    double length = 0.0;
    for (size_t i = 0; i < P.size(); ++i) {
        uv.push_back(P[i].uv);
        ring.push_back(static_cast<int>(i));
        length += (P[(i + 1) % P.size()].xyz - P[i].xyz).norm();
    }
    double area = 0.0;
    for (const auto& t : mesh::triangulate_polygon(uv, ring, {}, deadline)) {
        const Eigen::Vector2d c = (uv[t[0]] + uv[t[1]] + uv[t[2]]) / 3.0;
        const geom::SurfaceDerivatives d = surface.derivatives(c.x(), c.y());
        area += 0.5 * std::abs(cross(uv[t[1]] - uv[t[0]], uv[t[2]] - uv[t[0]])) * d.Su.cross(d.Sv).norm();
    }
    return length > 0.0 ? 2.0 * area / length : 0.0;
}

// A piece's extent on the surface, for pieces whose mean width is below min_width.
struct PieceExtent {
    double width = 0.0;  // 2 x the largest distance found from a sample inside to the boundary
    double area = 0.0;   // on the surface (sub-triangle centroid rule)
    bool wide = false;   // a sample lies farther than `reach` from the boundary
};

// Bounds on piece_extent's work: halvings of a boundary segment while its chord
// sags (2^12 parts), subdivisions per side of a triangle for samples (a triangle
// 16 reaches across still has samples reach / 2 apart, wider ones coarser), and
// segment parts filed in the grid (its cells grow past `reach` to keep within it).
constexpr int kMaxBoundaryDepth = 12;
constexpr int kMaxSampleDivisions = 16;
constexpr double kMaxGridParts = 2e5;

// S along the uv segment a -> b as points after S(a) (S(b) last), halved while the
// chord's midpoint lies more than `sag` from the surface's.
void surface_chords(const geom::NurbsSurface& S, const Eigen::Vector2d& a, const Eigen::Vector3d& A,
                    const Eigen::Vector2d& b, const Eigen::Vector3d& B, double sag, int depth,
                    std::vector<Eigen::Vector3d>* out) {
    const Eigen::Vector2d m = 0.5 * (a + b);
    const Eigen::Vector3d M = S.evaluate(m.x(), m.y());
    if (depth < kMaxBoundaryDepth && (M - 0.5 * (A + B)).norm() > sag) {
        surface_chords(S, a, A, m, M, sag, depth + 1, out);
        surface_chords(S, m, M, b, B, sag, depth + 1, out);
        return;
    }
    out->push_back(B);
}

// Width and area of a piece on the surface. The boundary is S along the piece's
// (u,v) polygon (chords within reach / 10); samples are the centroids of each
// (u,v) triangle's N x N subdivision, N such that they lie about reach / 2 apart
// (a point deeper than reach has one within reach / 2; thin triangles get one).
// Distances to the boundary are looked up in a grid of cells at least `reach`
// wide (at most kMaxGridParts segment parts filed), so a sample with no boundary
// within reach is found without scanning: the piece is then wide.
PieceExtent piece_extent(const std::vector<PolylinePoint>& P, const geom::NurbsSurface& S, double reach,
                         mesh::Deadline* deadline) {
    PieceExtent e;
    const size_t n = P.size();
    std::vector<Eigen::Vector2d> uv(n);
    std::vector<Eigen::Vector3d> X(n);
    std::vector<int> ring(n);
    for (size_t i = 0; i < n; ++i) {
        uv[i] = P[i].uv;
        X[i] = S.evaluate(uv[i].x(), uv[i].y());
        ring[i] = static_cast<int>(i);
    }
    std::vector<Eigen::Vector3d> boundary{X[0]};
    for (size_t i = 0; i < n; ++i)
        surface_chords(S, uv[i], X[i], uv[(i + 1) % n], X[(i + 1) % n], 0.1 * reach, 0, &boundary);
    // Segments split into parts no longer than a cell, each part filed under the
    // cells its box touches: a boundary point within `reach` of x lies in one of
    // the 27 cells around x's.
    double length = 0.0;
    for (size_t k = 0; k + 1 < boundary.size(); ++k) length += (boundary[k + 1] - boundary[k]).norm();
    const double cell = std::max(reach, length / kMaxGridParts);
    std::unordered_map<GridCell, std::vector<int>, GridCellHash> grid;
    for (size_t k = 0; k + 1 < boundary.size(); ++k) {
        const Eigen::Vector3d a = boundary[k], b = boundary[k + 1];
        const int parts = std::max(1, static_cast<int>(std::ceil((b - a).norm() / cell)));
        for (int q = 0; q < parts; ++q) {
            const Eigen::Vector3d p0 = a + (b - a) * q / parts, p1 = a + (b - a) * (q + 1) / parts;
            const GridCell lo = GridCell::of(p0.cwiseMin(p1), cell), hi = GridCell::of(p0.cwiseMax(p1), cell);
            for (long long x = lo.x; x <= hi.x; ++x)
                for (long long y = lo.y; y <= hi.y; ++y)
                    for (long long z = lo.z; z <= hi.z; ++z) {
                        std::vector<int>& cell = grid[{x, y, z}];
                        if (cell.empty() || cell.back() != static_cast<int>(k)) cell.push_back(static_cast<int>(k));
                    }
        }
    }
    auto depth = [&](const Eigen::Vector3d& x) {
        const GridCell c = GridCell::of(x, cell);
        double best = std::numeric_limits<double>::infinity();
        for (long long dx = -1; dx <= 1; ++dx)
            for (long long dy = -1; dy <= 1; ++dy)
                for (long long dz = -1; dz <= 1; ++dz) {
                    auto it = grid.find({c.x + dx, c.y + dy, c.z + dz});
                    if (it == grid.end()) continue;
                    for (int k : it->second) best = std::min(best, geom::segment_distance(x, boundary[k], boundary[k + 1]));
                }
        return best;
    };
    for (const auto& t : mesh::triangulate_polygon(uv, ring, {}, deadline)) {
        mesh::check_deadline_now(deadline, "trim loop repair");  // up to N^2 samples each
        const Eigen::Vector2d o = uv[t[0]];
        const double area3 = 0.5 * (X[t[1]] - X[t[0]]).cross(X[t[2]] - X[t[0]]).norm();
        const int N = geom::clamped_int(std::ceil(2.0 * std::sqrt(area3) / reach), 1, kMaxSampleDivisions);
        const Eigen::Vector2d e1 = (uv[t[1]] - o) / N, e2 = (uv[t[2]] - o) / N;
        const double sub_area = 0.5 * std::abs(cross(e1, e2));
        for (int a = 0; a < N; ++a)
            for (int b = 0; a + b < N; ++b)
                for (int up = 0; up < 2 && (up == 0 || a + b + 1 < N); ++up) {
                    const double f = up ? 2.0 / 3.0 : 1.0 / 3.0;
                    const Eigen::Vector2d c = o + (a + f) * e1 + (b + f) * e2;
                    const geom::SurfaceDerivatives d = S.derivatives(c.x(), c.y());
                    e.area += sub_area * d.Su.cross(d.Sv).norm();
                    if (e.wide) continue;
                    const double h = depth(d.S);
                    if (h > reach) {
                        e.wide = true;
                        e.width = 2.0 * reach;
                    } else {
                        e.width = std::max(e.width, 2.0 * h);
                    }
                }
    }
    return e;
}

// A point to insert into segment `segment` at fraction s.
struct Insertion {
    int segment;
    double s;
    Eigen::Vector2d uv;
};

// Cuts of segments i (a->b) and j (c->d) at their common points; adds to `cuts`
// and returns the number of intersection events. Points within snap of an end are
// the end itself (no cut on that segment).
int intersect(const std::vector<PolylinePoint>& P, int i, int j, double snap,
              std::vector<Insertion>* cuts) {
    const int n = static_cast<int>(P.size());
    const Eigen::Vector2d a = P[i].uv, b = P[(i + 1) % n].uv, c = P[j].uv, d = P[(j + 1) % n].uv;
    const Eigen::Vector2d r = b - a, s = d - c;
    const double rl = r.norm(), sl = s.norm();
    if (rl == 0.0 || sl == 0.0) return 0;
    const bool adjacent = (i + 1) % n == j || (j + 1) % n == i;
    // Cut segment k (p0 -> p1, length len) at point x, unless x is near an end.
    auto cut = [&](int k, const Eigen::Vector2d& p0, const Eigen::Vector2d& p1, double len,
                   const Eigen::Vector2d& x) {
        const double f = (x - p0).dot(p1 - p0) / (len * len);
        if ((x - p0).norm() <= snap || (x - p1).norm() <= snap || f <= 0.0 || f >= 1.0) return false;
        cuts->push_back({k, f, x});
        return true;
    };
    const double denom = cross(r, s);
    if (std::abs(denom) > 1e-12 * rl * sl) {
        if (adjacent) return 0;  // they meet at their shared vertex only
        const double alpha = cross(c - a, s) / denom, beta = cross(c - a, r) / denom;
        const double ta = snap / rl, tb = snap / sl;
        if (alpha < -ta || alpha > 1 + ta || beta < -tb || beta > 1 + tb) return 0;
        Eigen::Vector2d x = a + std::clamp(alpha, 0.0, 1.0) * r;
        // Snap to a vertex of either segment so both copies coincide exactly.
        for (const Eigen::Vector2d& v : {a, b, c, d})
            if ((x - v).norm() <= snap) x = v;
        const bool on_ab_end = (x - a).norm() <= snap || (x - b).norm() <= snap;
        const bool on_cd_end = (x - c).norm() <= snap || (x - d).norm() <= snap;
        // Vertex on vertex: nothing to cut; split_at_repeats separates the loops.
        if (on_ab_end && on_cd_end) return 0;
        cut(i, a, b, rl, x);
        cut(j, c, d, sl, x);
        return 1;
    }
    // Parallel: collinear overlap cuts each segment at the other's ends.
    if (std::abs(cross(r, c - a)) / rl > snap) return 0;
    int events = 0;
    for (const Eigen::Vector2d& x : {c, d}) events += cut(i, a, b, rl, x);
    for (const Eigen::Vector2d& x : {a, b}) events += cut(j, c, d, sl, x);
    return events;
}

// P with the cuts inserted, in order along each segment. Cuts are bucketed by
// segment (a counting sort) and each bucket sorted by its fraction, so that a
// hostile loop with millions of crossings stays within the deadline's checks.
std::vector<PolylinePoint> insert_cuts(const std::vector<PolylinePoint>& P,
                                       const std::vector<Insertion>& cuts, mesh::Deadline* deadline) {
    const int n = static_cast<int>(P.size());
    std::vector<size_t> start(n + 1, 0);
    for (const Insertion& c : cuts) ++start[c.segment + 1];
    for (int i = 0; i < n; ++i) start[i + 1] += start[i];
    std::vector<Insertion> sorted(cuts.size());
    std::vector<size_t> next(start.begin(), start.end() - 1);
    for (const Insertion& c : cuts) sorted[next[c.segment]++] = c;
    std::vector<PolylinePoint> Q;
    Q.reserve(P.size() + cuts.size());
    for (int i = 0; i < n; ++i) {
        mesh::check_deadline(deadline, "trim loop repair");
        const auto first = sorted.begin() + start[i], last = sorted.begin() + start[i + 1];
        std::sort(first, last, [](const Insertion& a, const Insertion& b) { return a.s < b.s; });
        Q.push_back(P[i]);
        for (auto c = first; c != last; ++c) {
            PolylinePoint x = lerp(P[i], P[(i + 1) % n], c->s);
            x.uv = c->uv;
            Q.push_back(x);
        }
    }
    return Q;
}

// Splits a closed sequence at points it visits twice (within snap).
std::vector<std::vector<PolylinePoint>> split_at_repeats(const std::vector<PolylinePoint>& Q,
                                                         double snap, mesh::Deadline* deadline) {
    Eigen::AlignedBox2d box;
    for (const auto& p : Q) box.extend(p.uv);
    const double cell = std::max(snap, 1e-12 * (1.0 + box.diagonal().norm() +
                                                box.min().cwiseAbs().maxCoeff()));
    std::map<std::pair<long long, long long>, std::vector<int>> grid;  // cell -> stack indices
    auto key = [&](const Eigen::Vector2d& uv) {
        return std::make_pair(static_cast<long long>(std::floor(uv.x() / cell)),
                              static_cast<long long>(std::floor(uv.y() / cell)));
    };
    std::vector<PolylinePoint> stack;
    std::vector<std::vector<PolylinePoint>> loops;
    for (const PolylinePoint& q : Q) {
        mesh::check_deadline(deadline, "trim loop repair");
        const auto k = key(q.uv);
        int found = -1;
        for (long long dx = -1; dx <= 1 && found < 0; ++dx)
            for (long long dy = -1; dy <= 1 && found < 0; ++dy) {
                auto it = grid.find({k.first + dx, k.second + dy});
                if (it == grid.end()) continue;
                for (int idx : it->second)
                    if (idx < static_cast<int>(stack.size()) &&
                        (stack[idx].uv - q.uv).norm() <= snap) {
                        found = idx;
                        break;
                    }
            }
        if (found >= 0) {
            loops.emplace_back(stack.begin() + found, stack.end());
            for (size_t r = found + 1; r < stack.size(); ++r) {
                auto& cellv = grid[key(stack[r].uv)];
                cellv.erase(std::remove(cellv.begin(), cellv.end(), static_cast<int>(r)), cellv.end());
            }
            stack.resize(found + 1);
            continue;
        }
        grid[k].push_back(static_cast<int>(stack.size()));
        stack.push_back(q);
    }
    loops.push_back(std::move(stack));
    return loops;
}

}  // namespace

double signed_area(const std::vector<PolylinePoint>& P) {
    double A = 0.0;
    for (size_t i = 0; i < P.size(); ++i) A += cross(P[i].uv, P[(i + 1) % P.size()].uv);
    return 0.5 * A;
}

TrimPolygon join_trim_loop(const std::vector<TrimPolyline>& coedges, bool outer, double snap_uv,
                           LoopRepairReport* report) {
    TrimPolygon polygon;
    polygon.outer = outer;
    double max_gap = 0.0;
    for (const TrimPolyline& c : coedges) {
        if (c.points.empty()) continue;
        size_t first = 0;
        if (!polygon.points.empty()) {
            const double gap = (c.points.front().uv - polygon.points.back().uv).norm();
            max_gap = std::max(max_gap, gap);
            if (gap <= snap_uv) first = 1;
        }
        polygon.points.insert(polygon.points.end(), c.points.begin() + first, c.points.end());
    }
    if (polygon.points.size() > 1) {
        const double gap = (polygon.points.back().uv - polygon.points.front().uv).norm();
        max_gap = std::max(max_gap, gap);
        if (gap <= snap_uv) polygon.points.pop_back();
    }
    if (report) report->max_gap = std::max(report->max_gap, max_gap);
    return polygon;
}

std::vector<TrimPolygon> repair_trim_loop(const TrimPolygon& loop, double snap_uv,
                                          LoopRepairReport* report, bool face_reversed,
                                          const geom::NurbsSurface* surface, double min_width,
                                          mesh::Deadline* deadline) {
    LoopRepairReport local;
    LoopRepairReport& rep = report ? *report : local;
    std::vector<PolylinePoint> P = merge_close(loop.points, snap_uv);
    if (P.size() < 3) {
        rep.dropped += 1;
        return {};
    }
    const double area = signed_area(P);
    const bool expected_ccw = loop.outer != face_reversed;  // face.h's convention
    if ((expected_ccw && area < 0.0) || (!expected_ccw && area > 0.0)) rep.reoriented = true;
    if ((loop.outer && area < 0.0) || (!loop.outer && area > 0.0)) std::reverse(P.begin(), P.end());

    // Sweep over u: segments sorted by their smallest u; a pair is tested while
    // the later segment starts before the earlier one ends.
    const int n = static_cast<int>(P.size());
    std::vector<int> order(n);
    std::vector<double> lo(n), hi(n);
    for (int i = 0; i < n; ++i) {
        order[i] = i;
        lo[i] = std::min(P[i].uv.x(), P[(i + 1) % n].uv.x()) - snap_uv;
        hi[i] = std::max(P[i].uv.x(), P[(i + 1) % n].uv.x()) + snap_uv;
    }
    std::sort(order.begin(), order.end(), [&](int a, int b) { return lo[a] < lo[b]; });
    std::vector<Insertion> cuts;
    for (int oi = 0; oi < n; ++oi)
        for (int oj = oi + 1; oj < n && lo[order[oj]] <= hi[order[oi]]; ++oj) {
            mesh::check_deadline(deadline, "trim loop repair");
            const int i = order[oi], j = order[oj];
            const double vlo_i = std::min(P[i].uv.y(), P[(i + 1) % n].uv.y()) - snap_uv;
            const double vhi_i = std::max(P[i].uv.y(), P[(i + 1) % n].uv.y()) + snap_uv;
            const double vlo_j = std::min(P[j].uv.y(), P[(j + 1) % n].uv.y());
            const double vhi_j = std::max(P[j].uv.y(), P[(j + 1) % n].uv.y());
            if (vlo_j > vhi_i || vhi_j < vlo_i) continue;
            rep.crossings += intersect(P, std::min(i, j), std::max(i, j), snap_uv, &cuts);
        }

    mesh::check_deadline_now(deadline, "trim loop repair");
    std::vector<PolylinePoint> Q = insert_cuts(P, cuts, deadline);
    Q = merge_close(Q, snap_uv);

    std::vector<TrimPolygon> out;
    const double reach = kWideRegionFactor * min_width;
    auto record_drop = [&](const PieceExtent* extent) {
        rep.dropped += 1;
        if (!extent) return;
        rep.dropped_width = std::max(rep.dropped_width, extent->width);
        rep.dropped_area += extent->area;
    };
    for (std::vector<PolylinePoint>& piece : split_at_repeats(Q, snap_uv, deadline)) {
        mesh::check_deadline_now(deadline, "trim loop repair");
        piece = merge_close(piece, snap_uv);
        const double a = piece.size() >= 3 ? signed_area(piece) : 0.0;
        if (piece.size() < 3 || std::abs(a) <= 0.5 * snap_uv * perimeter(piece)) {
            if (piece.size() >= 3 && surface && reach > 0.0) {
                const PieceExtent extent = piece_extent(piece, *surface, reach, deadline);
                record_drop(&extent);
            } else {
                record_drop(nullptr);
            }
            continue;
        }
        if ((loop.outer && a < 0.0) || (!loop.outer && a > 0.0))
            std::reverse(piece.begin(), piece.end());
        if (!cuts.empty() && surface && min_width > 0.0 && width_on_surface(piece, *surface, deadline) <= min_width) {
            // Thin on average; a sliver only if thin everywhere.
            const PieceExtent extent = piece_extent(piece, *surface, reach, deadline);
            if (!extent.wide) {
                record_drop(&extent);
                continue;
            }
            rep.kept_wide += 1;
        }
        out.push_back({std::move(piece), loop.outer});
    }
    rep.split_loops += std::max(0, static_cast<int>(out.size()) - 1);
    return out;
}

}  // namespace trimkit::tess
