#include "tess/sew_free_coedges.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "tess/share_edge_points.h"

namespace trimkit::tess {

namespace {

// Points per trace for the pairing test, and for telling the direction of closed
// traces (whose ends coincide) apart.
constexpr int kTraceIntervals = 16;
constexpr int kDirectionSamples = 64;
// A trace end with more ends than this around it (stacked copies of one face, a
// fan of coincident curves) is not sewn: which pairs belong together is not clear
// there, and the pairing would cost the square of their number.
constexpr std::size_t kMaxEndsNearby = 32;
// Candidates per trace end tried, nearest ends first.
constexpr std::size_t kMaxCandidates = 4;

struct Trace {
    int face = 0, loop = 0, coedge = 0;
    std::vector<Eigen::Vector3d> points;  // S(c(t)) at kTraceIntervals + 1 uniform t
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

std::vector<Trace> free_traces(const geom::Model& model, double distance) {
    std::vector<Trace> traces;
    for (size_t f = 0; f < model.faces.size(); ++f)
        for (size_t l = 0; l < model.faces[f].loops.size(); ++l)
            for (size_t c = 0; c < model.faces[f].loops[l].coedges.size(); ++c) {
                const geom::Coedge& coedge = model.faces[f].loops[l].coedges[c];
                if (coedge.edge >= 0) continue;
                Trace trace{static_cast<int>(f), static_cast<int>(l), static_cast<int>(c),
                            trace_points(model.faces[f], coedge, kTraceIntervals), 0.0};
                for (int k = 0; k < kTraceIntervals; ++k)
                    trace.length += (trace.points[k + 1] - trace.points[k]).norm();
                if (trace.length > 2.0 * distance && std::isfinite(trace.length)) traces.push_back(std::move(trace));
            }
    return traces;
}

// Buckets of the traces' end points by a grid of `cell`-sized cubes.
class EndGrid {
public:
    explicit EndGrid(double cell) : cell_(cell) {}
    void add(const Eigen::Vector3d& p, int trace) { cells_[key(cell_of(p))].push_back(trace); }
    // Traces with an end in the 27 cells around p; none when more than kMaxEndsNearby.
    std::vector<int> near(const Eigen::Vector3d& p) const {
        std::vector<const std::vector<int>*> lists;
        std::size_t count = 0;
        const auto c = cell_of(p);
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz) {
                    const auto it = cells_.find(key({c[0] + dx, c[1] + dy, c[2] + dz}));
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
    std::array<std::int64_t, 3> cell_of(const Eigen::Vector3d& p) const {
        return {static_cast<std::int64_t>(std::floor(p.x() / cell_)), static_cast<std::int64_t>(std::floor(p.y() / cell_)),
                static_cast<std::int64_t>(std::floor(p.z() / cell_))};
    }
    static std::uint64_t key(const std::array<std::int64_t, 3>& c) {
        std::uint64_t h = 1469598103934665603ull;
        for (std::int64_t v : c) h = (h ^ static_cast<std::uint64_t>(v)) * 1099511628211ull;
        return h;
    }
    double cell_;
    std::unordered_map<std::uint64_t, std::vector<int>> cells_;
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
    return nearest(a.points[kTraceIntervals / 3]) < nearest(a.points[(2 * kTraceIntervals) / 3]);
}

// Largest distance of `points` (in the direction of the coedge when `along`) from
// the coedge's trace on its face.
double trace_gap(const geom::Model& model, const Trace& on, std::vector<Eigen::Vector3d> points, bool along) {
    const geom::Face& face = model.faces[on.face];
    geom::Coedge coedge = face.loops[on.loop].coedges[on.coedge];
    coedge.edge_reversed = !along;
    return share_edge_points(face.surface, coedge, points).max_gap;
}

// The pair's gap both ways, or +inf when the traces do not run along each other.
double pair_gap(const geom::Model& model, const Trace& a, const Trace& b, bool same_direction, double distance) {
    if (std::abs(a.length - b.length) > 0.1 * std::max(a.length, b.length) + 2.0 * distance) return INFINITY;
    const double ab = trace_gap(model, b, a.points, same_direction);
    if (!(ab <= distance)) return INFINITY;
    const double ba = trace_gap(model, a, b.points, same_direction);
    return ba <= distance ? std::max(ab, ba) : INFINITY;
}

std::vector<Candidate> candidates(const geom::Model& model, const std::vector<Trace>& traces, double distance) {
    EndGrid grid(distance);
    for (size_t i = 0; i < traces.size(); ++i) {
        grid.add(traces[i].points.front(), static_cast<int>(i));
        grid.add(traces[i].points.back(), static_cast<int>(i));
    }
    const auto close = [&](const Eigen::Vector3d& p, const Eigen::Vector3d& q) { return (p - q).norm() <= distance; };
    std::vector<Candidate> found;
    for (size_t i = 0; i < traces.size(); ++i) {
        const Trace& a = traces[i];
        std::vector<std::pair<double, int>> ends;  // (distance of both ends, trace)
        // Both ends must match: the back is looked up where the front is crowded (a pole).
        std::vector<int> nearby = grid.near(a.points.front());
        if (nearby.empty()) nearby = grid.near(a.points.back());
        for (int j : nearby) {
            if (j <= static_cast<int>(i)) continue;
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
            const double gap = pair_gap(model, a, b, same_direction, distance);
            if (std::isfinite(gap)) found.push_back({static_cast<int>(i), j, same_direction, gap});
        }
    }
    return found;
}

}  // namespace

SewingReport sew_free_coedges(geom::Model& model, double distance) {
    SewingReport report;
    if (!(distance > 0.0) || !std::isfinite(distance)) return report;
    const std::vector<Trace> traces = free_traces(model, distance);
    std::vector<Candidate> found = candidates(model, traces, distance);
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
