#include "tess/sew_free_coedges.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "mesh/grid_cell.h"
#include "mesh/parallel_for.h"
#include "tess/share_edge_points.h"
#include "geom/clamped_int.h"

namespace trimkit::tess {

namespace {

// Points per trace for the pairing test, and for telling the direction of closed
// traces (whose ends coincide) apart.
constexpr int kTraceIntervals = 16;
// The pairing test's points per trace: kTraceIntervals, or kPointsPerSpan per span of
// the coedge's curve when it has more (a p-curve approximated span by span strays
// between its knots: equal_tee_faces had traces 2 T apart that agreed at 17 points),
// up to kMaxTraceIntervals.
constexpr int kPointsPerSpan = 4;
constexpr int kMaxTraceIntervals = 1024;
constexpr int kDirectionSamples = 64;
// A trace end with more ends than this around it (stacked copies of one face, a
// fan of coincident curves) is not sewn: which pairs belong together is not clear
// there, and the pairing would cost the square of their number.
constexpr std::size_t kMaxEndsNearby = 32;
// Candidates per trace end tried, nearest ends first.
constexpr std::size_t kMaxCandidates = 4;

struct Trace {
    int face = 0, loop = 0, coedge = 0;
    std::vector<Eigen::Vector3d> points;  // S(c(t)) at uniform t, trace_intervals + 1 of them
    double length = 0.0;
};

struct Candidate {
    int a = 0, b = 0;
    bool same_direction = false;
    double gap = 0.0;
};

std::vector<Eigen::Vector3d> trace_points(const geom::Face& face, const geom::Coedge& coedge, int intervals) {
    const auto [t0, t1] = coedge.curve.domain();
    std::vector<Eigen::Vector3d> points;
    points.reserve(intervals + 1);
    for (int k = 0; k <= intervals; ++k) {
        const double t = k == intervals ? t1 : t0 + (t1 - t0) * k / intervals;
        const Eigen::Vector2d uv = coedge.curve.evaluate(t);
        points.push_back(face.surface.evaluate(uv.x(), uv.y()));
    }
    return points;
}

int trace_intervals(const geom::NurbsCurve2d& c) {
    const std::vector<double>& U = c.knots();
    int spans = 0;
    for (std::size_t k = 1; k < U.size(); ++k) spans += U[k] > U[k - 1];
    return std::clamp(kPointsPerSpan * spans, kTraceIntervals, kMaxTraceIntervals);
}

std::vector<Trace> free_traces(const geom::Model& model, double distance, int threads) {
    std::vector<Trace> traces;
    for (size_t f = 0; f < model.faces.size(); ++f)
        for (size_t l = 0; l < model.faces[f].loops.size(); ++l)
            for (size_t c = 0; c < model.faces[f].loops[l].coedges.size(); ++c)
                if (model.faces[f].loops[l].coedges[c].edge < 0)
                    traces.push_back({static_cast<int>(f), static_cast<int>(l), static_cast<int>(c), {}, 0.0});
    // The points (each a surface evaluation) on the threads.
    mesh::parallel_for(static_cast<int>(traces.size()), threads, [&](int i) {
        Trace& trace = traces[i];
        const geom::Face& face = model.faces[trace.face];
        const geom::Coedge& coedge = face.loops[trace.loop].coedges[trace.coedge];
        const int intervals = trace_intervals(coedge.curve);
        trace.points = trace_points(face, coedge, intervals);
        for (int k = 0; k < intervals; ++k) trace.length += (trace.points[k + 1] - trace.points[k]).norm();
    });
    traces.erase(std::remove_if(traces.begin(), traces.end(),
                                [&](const Trace& t) { return !(t.length > 2.0 * distance && std::isfinite(t.length)); }),
                 traces.end());
    return traces;
}

// Buckets of the traces' end points by a grid of `cell`-sized cubes.
class EndGrid {
public:
    explicit EndGrid(double cell) : cell_(cell) {}
    void add(const Eigen::Vector3d& p, int trace) { cells_[mesh::GridCell::of(p, cell_)].push_back(trace); }
    // Traces with an end in the 27 cells around p; none when more than kMaxEndsNearby.
    std::vector<int> near(const Eigen::Vector3d& p) const {
        std::vector<const std::vector<int>*> lists;
        std::size_t count = 0;
        const mesh::GridCell c = mesh::GridCell::of(p, cell_);
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz) {
                    const auto it = cells_.find({c.x + dx, c.y + dy, c.z + dz});
                    if (it == cells_.end()) continue;
                    lists.push_back(&it->second);
                    count += it->second.size();
                }
        std::vector<int> found;
        if (count > kMaxEndsNearby) return found;
        for (const std::vector<int>* list : lists) found.insert(found.end(), list->begin(), list->end());
        std::sort(found.begin(), found.end());
        found.erase(std::unique(found.begin(), found.end()), found.end());
        return found;
    }

private:
    double cell_;
    std::unordered_map<mesh::GridCell, std::vector<int>, mesh::GridCellHash> cells_;
};

// Whether b runs along a in a's direction, from where a's points at 1/3 and 2/3
// fall on b's densely sampled trace (closed traces, whose ends tell nothing).
bool runs_along(const geom::Model& model, const Trace& a, const Trace& b) {
    const geom::Face& face = model.faces[b.face];
    const std::vector<Eigen::Vector3d> dense =
        trace_points(face, face.loops[b.loop].coedges[b.coedge], kDirectionSamples);
    const auto nearest = [&](const Eigen::Vector3d& x) {
        int best = 0;
        for (int k = 1; k <= kDirectionSamples; ++k)
            if ((dense[k] - x).squaredNorm() < (dense[best] - x).squaredNorm()) best = k;
        return best;
    };
    const std::size_t n = a.points.size() - 1;
    return nearest(a.points[n / 3]) < nearest(a.points[(2 * n) / 3]);
}

// Largest distance of `points` (in the direction of the coedge when `along`) from
// the coedge's trace on its face.
double trace_gap(const geom::Model& model, const Trace& on, std::vector<Eigen::Vector3d> points, bool along) {
    const geom::Face& face = model.faces[on.face];
    geom::Coedge coedge = face.loops[on.loop].coedges[on.coedge];
    coedge.edge_reversed = !along;
    return share_edge_points(face.surface, coedge, points).max_gap;
}

// Two coedges of one face pair only as its seam: their (u,v) ends half a domain or more
// apart in u or in v (a closed surface's two sides of one curve). Two sides of a face
// narrower than the distance are different curves: sewn, they became one polyline and
// the face's mesh collapsed to two triangles, 44 T from the surface (a ribbon 0.15 wide
// at T = 2), which the face's own check could not see.
bool one_face_but_no_seam(const geom::Model& model, const Trace& a, const Trace& b, bool same_direction) {
    if (a.face != b.face) return false;
    const geom::Face& face = model.faces[a.face];
    const auto end = [&](const Trace& t, bool last) {
        const geom::NurbsCurve2d& c = face.loops[t.loop].coedges[t.coedge].curve;
        return c.evaluate(last ? c.domain().second : c.domain().first);
    };
    const auto [u0, u1] = face.surface.domain_u();
    const auto [v0, v1] = face.surface.domain_v();
    for (bool last : {false, true}) {
        const Eigen::Vector2d d = (end(a, last) - end(b, same_direction ? last : !last)).cwiseAbs();
        if (!(d.x() >= 0.5 * (u1 - u0) || d.y() >= 0.5 * (v1 - v0))) return true;
    }
    return false;
}

// The pair's gap both ways, or +inf when the traces do not run along each other.
double pair_gap(const geom::Model& model, const Trace& a, const Trace& b, bool same_direction, double distance) {
    if (std::abs(a.length - b.length) > 0.1 * std::max(a.length, b.length) + 2.0 * distance) return INFINITY;
    const double ab = trace_gap(model, b, a.points, same_direction);
    if (!(ab <= distance)) return INFINITY;
    const double ba = trace_gap(model, a, b.points, same_direction);
    return ba <= distance ? std::max(ab, ba) : INFINITY;
}

// The pairs, trace by trace (on `threads` threads: each pair's gap samples both
// surfaces), in trace order.
std::vector<Candidate> candidates(const geom::Model& model, const std::vector<Trace>& traces, double distance,
                                  int threads) {
    EndGrid grid(distance);
    for (size_t i = 0; i < traces.size(); ++i) {
        grid.add(traces[i].points.front(), static_cast<int>(i));
        grid.add(traces[i].points.back(), static_cast<int>(i));
    }
    const auto close = [&](const Eigen::Vector3d& p, const Eigen::Vector3d& q) { return (p - q).norm() <= distance; };
    std::vector<std::vector<Candidate>> per_trace(traces.size());
    mesh::parallel_for(static_cast<int>(traces.size()), threads, [&](int i) {
        const Trace& a = traces[i];
        std::vector<Candidate>& found = per_trace[i];
        std::vector<std::pair<double, int>> ends;  // (distance of both ends, trace)
        // Both ends must match: the back is looked up where the front is crowded (a pole).
        std::vector<int> nearby = grid.near(a.points.front());
        if (nearby.empty()) nearby = grid.near(a.points.back());
        for (int j : nearby) {
            if (j <= i) continue;
            const Trace& b = traces[j];
            const double opposite = (a.points.front() - b.points.back()).norm() + (a.points.back() - b.points.front()).norm();
            const double same = (a.points.front() - b.points.front()).norm() + (a.points.back() - b.points.back()).norm();
            if (std::min(opposite, same) <= 2.0 * distance) ends.emplace_back(std::min(opposite, same), j);
        }
        std::sort(ends.begin(), ends.end());
        if (ends.size() > kMaxCandidates) ends.resize(kMaxCandidates);
        for (const auto& [ignored, j] : ends) {
            const Trace& b = traces[j];
            const bool opposite = close(a.points.front(), b.points.back()) && close(a.points.back(), b.points.front());
            const bool same = close(a.points.front(), b.points.front()) && close(a.points.back(), b.points.back());
            if (!opposite && !same) continue;
            const bool same_direction = opposite && same ? runs_along(model, a, b) : same;
            if (one_face_but_no_seam(model, a, b, same_direction)) continue;
            const double gap = pair_gap(model, a, b, same_direction, distance);
            if (std::isfinite(gap)) found.push_back({i, j, same_direction, gap});
        }
    });
    std::vector<Candidate> found;
    for (const std::vector<Candidate>& list : per_trace) found.insert(found.end(), list.begin(), list.end());
    return found;
}

// ---- Splitting: a trace end on another trace's interior (a T-vertex of the faces
// that the file left unsplit, or the start of a closed curve that the other face's
// closed curve starts elsewhere) splits that coedge there, so that the pairing
// below sees whole curves on both sides.

// Samples per trace for finding the trace an end lies on, at most.
constexpr int kMaxLookupSamples = 4096;
// Golden-section steps refining an end's parameter on the other trace.
constexpr int kRefineSteps = 60;
// Splits of one coedge, at most (a curve with more T-vertices is left whole).
constexpr std::size_t kMaxSplits = 64;

struct Lookup {
    int trace = 0;
    double t = 0.0;
};

// Sample points of every trace, `spacing` apart at most (up to kMaxLookupSamples),
// bucketed in a grid of `spacing` cubes.
class TraceGrid {
public:
    TraceGrid(const geom::Model& model, const std::vector<Trace>& traces, double spacing) : grid_(spacing) {
        for (std::size_t i = 0; i < traces.size(); ++i) {
            const Trace& trace = traces[i];
            const geom::Face& face = model.faces[trace.face];
            const geom::Coedge& coedge = face.loops[trace.loop].coedges[trace.coedge];
            const int n = geom::clamped_int(std::ceil(trace.length / spacing), kTraceIntervals, kMaxLookupSamples);
            const auto [t0, t1] = coedge.curve.domain();
            const std::vector<Eigen::Vector3d> points = trace_points(face, coedge, n);
            for (int k = 0; k <= n; ++k) {
                samples_.push_back({static_cast<int>(i), k == n ? t1 : t0 + (t1 - t0) * k / n});
                grid_.add(points[k], static_cast<int>(samples_.size()) - 1);
                positions_.push_back(points[k]);
            }
        }
    }
    // Samples near p (none where crowded, EndGrid::near), as (trace, t).
    std::vector<std::pair<Lookup, Eigen::Vector3d>> near(const Eigen::Vector3d& p) const {
        std::vector<std::pair<Lookup, Eigen::Vector3d>> found;
        for (int k : grid_.near(p)) found.push_back({samples_[k], positions_[k]});
        return found;
    }

private:
    EndGrid grid_;
    std::vector<Lookup> samples_;
    std::vector<Eigen::Vector3d> positions_;
};

// The parameter of `trace` nearest x in [a, b], by golden-section search.
double nearest_parameter(const geom::Model& model, const Trace& trace, const Eigen::Vector3d& x, double a, double b) {
    const geom::Face& face = model.faces[trace.face];
    const geom::NurbsCurve2d& c = face.loops[trace.loop].coedges[trace.coedge].curve;
    const auto d2 = [&](double t) {
        const Eigen::Vector2d uv = c.evaluate(t);
        return (face.surface.evaluate(uv.x(), uv.y()) - x).squaredNorm();
    };
    const double g = 0.5 * (std::sqrt(5.0) - 1.0);
    double lo = a, hi = b, m1 = hi - g * (hi - lo), m2 = lo + g * (hi - lo);
    double f1 = d2(m1), f2 = d2(m2);
    for (int it = 0; it < kRefineSteps; ++it) {
        if (f1 < f2) {
            hi = m2, m2 = m1, f2 = f1, m1 = hi - g * (hi - lo), f1 = d2(m1);
        } else {
            lo = m1, m1 = m2, f1 = f2, m2 = lo + g * (hi - lo), f2 = d2(m2);
        }
    }
    return 0.5 * (lo + hi);
}

Eigen::Vector3d trace_at(const geom::Model& model, const Trace& trace, double t) {
    const geom::Face& face = model.faces[trace.face];
    const Eigen::Vector2d uv = face.loops[trace.loop].coedges[trace.coedge].curve.evaluate(t);
    return face.surface.evaluate(uv.x(), uv.y());
}

// For each trace, the parameters where other traces' ends lie on its interior (more
// than 2 x distance from its own ends in 3D), sorted.
std::vector<std::vector<double>> split_parameters(const geom::Model& model, const std::vector<Trace>& traces,
                                                  double distance, int threads) {
    std::vector<double> lengths;
    for (const Trace& trace : traces) lengths.push_back(trace.length);
    std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
    const double spacing = std::max(4.0 * distance, lengths[lengths.size() / 2] / kTraceIntervals);
    const TraceGrid grid(model, traces, spacing);
    // Per trace j, the (trace, parameter) splits its ends make, on the threads; then
    // gathered in j's order, each trace's first kMaxSplits kept.
    std::vector<std::vector<std::pair<int, double>>> found(traces.size());
    mesh::parallel_for(static_cast<int>(traces.size()), threads, [&](int j) {
        for (const Eigen::Vector3d& end : {traces[j].points.front(), traces[j].points.back()}) {
            std::vector<std::pair<Lookup, Eigen::Vector3d>> near = grid.near(end);
            std::sort(near.begin(), near.end(), [&](const auto& x, const auto& y) {
                return (x.second - end).squaredNorm() < (y.second - end).squaredNorm();
            });
            std::vector<int> seen;
            for (const auto& [sample, position] : near) {
                const Trace& on = traces[sample.trace];
                if (sample.trace == j ||
                    std::find(seen.begin(), seen.end(), sample.trace) != seen.end())
                    continue;
                seen.push_back(sample.trace);  // each trace once: its nearest sample
                if ((on.points.front() - end).norm() <= 2.0 * distance || (on.points.back() - end).norm() <= 2.0 * distance)
                    continue;
                const geom::Coedge& coedge = model.faces[on.face].loops[on.loop].coedges[on.coedge];
                const auto [t0, t1] = coedge.curve.domain();
                const double step = 2.0 * spacing / on.length * (t1 - t0);
                const double t = nearest_parameter(model, on, end, std::max(t0, sample.t - step), std::min(t1, sample.t + step));
                if ((trace_at(model, on, t) - end).norm() <= distance) found[j].emplace_back(sample.trace, t);
            }
        }
    });
    std::vector<std::vector<double>> splits(traces.size());
    for (const auto& list : found)
        for (const auto& [trace, t] : list)
            if (splits[trace].size() < kMaxSplits) splits[trace].push_back(t);
    for (std::vector<double>& ts : splits) std::sort(ts.begin(), ts.end());
    return splits;
}

// Replaces each trace's coedge by its pieces between the split parameters (pieces
// shorter than 2 x distance in 3D are merged into the next).
int apply_splits(geom::Model& model, const std::vector<Trace>& traces,
                 const std::vector<std::vector<double>>& splits, double distance) {
    std::map<std::tuple<int, int, int>, std::vector<double>> at;  // (face, loop, coedge) -> cuts
    for (std::size_t i = 0; i < traces.size(); ++i) {
        std::vector<double> cuts;
        Eigen::Vector3d last = traces[i].points.front();
        for (double t : splits[i]) {
            const Eigen::Vector3d p = trace_at(model, traces[i], t);
            if ((p - last).norm() > 2.0 * distance && (p - traces[i].points.back()).norm() > 2.0 * distance) {
                cuts.push_back(t);
                last = p;
            }
        }
        if (!cuts.empty()) at[{traces[i].face, traces[i].loop, traces[i].coedge}] = cuts;
    }
    int pieces = 0;
    for (auto it = at.rbegin(); it != at.rend(); ++it) {  // later coedges first: indices stay valid
        const auto [f, l, c] = it->first;
        std::vector<geom::Coedge>& coedges = model.faces[f].loops[l].coedges;
        const geom::Coedge whole = coedges[c];
        const auto [t0, t1] = whole.curve.domain();
        std::vector<double> ends{t0};
        ends.insert(ends.end(), it->second.begin(), it->second.end());
        ends.push_back(t1);
        std::vector<geom::Coedge> parts;
        for (std::size_t k = 0; k + 1 < ends.size(); ++k)
            parts.push_back(geom::Coedge{whole.curve.sub_curve(ends[k], ends[k + 1]), -1, false});
        coedges.erase(coedges.begin() + c);
        coedges.insert(coedges.begin() + c, parts.begin(), parts.end());
        pieces += static_cast<int>(parts.size()) - 1;
    }
    return pieces;
}

}  // namespace

SewingReport sew_free_coedges(geom::Model& model, double distance, int threads) {
    SewingReport report;
    if (!(distance > 0.0) || !std::isfinite(distance)) return report;
    {
        const std::vector<Trace> whole = free_traces(model, distance, threads);
        if (whole.empty()) return report;
        report.splits = apply_splits(model, whole, split_parameters(model, whole, distance, threads), distance);
    }
    const std::vector<Trace> traces = free_traces(model, distance, threads);
    std::vector<Candidate> found = candidates(model, traces, distance, threads);
    std::stable_sort(found.begin(), found.end(),
                     [](const Candidate& x, const Candidate& y) { return x.gap < y.gap; });
    std::vector<char> used(traces.size(), 0);
    for (const Candidate& pair : found) {
        if (used[pair.a] || used[pair.b]) continue;
        used[pair.a] = used[pair.b] = 1;
        const Trace& a = traces[pair.a];
        const Trace& b = traces[pair.b];
        const int e = static_cast<int>(model.edges.size());
        model.edges.push_back(geom::Edge{std::nullopt, a.points.front(), a.points.back()});
        geom::Coedge& first = model.faces[a.face].loops[a.loop].coedges[a.coedge];
        geom::Coedge& second = model.faces[b.face].loops[b.loop].coedges[b.coedge];
        first.edge = e;
        first.edge_reversed = false;
        second.edge = e;
        second.edge_reversed = !pair.same_direction;
        ++report.pairs;
        report.max_gap = std::max(report.max_gap, pair.gap);
    }
    return report;
}

}  // namespace trimkit::tess
