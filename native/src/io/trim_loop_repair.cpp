#include "io/trim_loop_repair.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geom/analytic_curves.h"

namespace trimkit::io {
namespace {

// Samples per coedge for the area polygon.
constexpr int kAreaSamples = 16;
// Largest loop reordered by the greedy chaining (quadratic in the count).
constexpr std::size_t kMaxReorder = 2000;

Eigen::Vector2d start_of(const geom::NurbsCurve2d& c) { return c.evaluate(c.domain().first); }
Eigen::Vector2d end_of(const geom::NurbsCurve2d& c) { return c.evaluate(c.domain().second); }

bool clamped_end(const geom::NurbsCurve2d& c, bool at_start) {
    const auto& U = c.knots();
    const int p = c.degree();
    if (at_start) return U[0] == U[p];
    return U[U.size() - 1] == U[U.size() - 1 - p];
}

// The curve with its first or last control point moved to `x` (only valid
// for a clamped end, where the curve passes through that point).
geom::NurbsCurve2d with_end(const geom::NurbsCurve2d& c, bool at_start, const Eigen::Vector2d& x) {
    std::vector<Eigen::Vector2d> P = c.points();
    (at_start ? P.front() : P.back()) = x;
    return geom::NurbsCurve2d(c.degree(), c.knots(), std::move(P),
                              c.is_rational() ? c.weights() : std::vector<double>{});
}

void reverse_coedge(geom::Coedge& e) {
    e.curve = e.curve.reversed();
    if (e.edge >= 0) e.edge_reversed = !e.edge_reversed;
}

double scaled_gap(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& extent) {
    return (a - b).cwiseQuotient(extent).norm();
}

double total_gap(const std::vector<geom::Coedge>& c, const Eigen::Vector2d& extent) {
    double g = 0;
    for (std::size_t i = 0; i < c.size(); ++i)
        g += scaled_gap(end_of(c[i].curve), start_of(c[(i + 1) % c.size()].curve), extent);
    return g;
}

}  // namespace

bool close_loop(geom::Loop& loop, const geom::NurbsSurface& surface, double model_tolerance,
                const std::string& label, std::vector<std::string>* warnings) {
    auto& C = loop.coedges;
    if (C.empty()) return false;
    const auto [u0, u1] = surface.domain_u();
    const auto [v0, v1] = surface.domain_v();
    const Eigen::Vector2d extent(std::max(u1 - u0, 1e-300), std::max(v1 - v0, 1e-300));

    // Greedy chaining when the given order leaves gaps.
    if (C.size() > 2 && C.size() <= kMaxReorder && total_gap(C, extent) > kSnapGapRelative) {
        std::vector<geom::Coedge> rest(C.begin() + 1, C.end()), chain{C.front()};
        while (!rest.empty()) {
            const Eigen::Vector2d tail = end_of(chain.back().curve);
            std::size_t best = 0;
            bool flip = false;
            double bd = std::numeric_limits<double>::infinity();
            for (std::size_t k = 0; k < rest.size(); ++k) {
                double ds = scaled_gap(tail, start_of(rest[k].curve), extent);
                double de = scaled_gap(tail, end_of(rest[k].curve), extent);
                if (ds < bd) { bd = ds; best = k; flip = false; }
                if (de < bd) { bd = de; best = k; flip = true; }
            }
            geom::Coedge e = rest[best];
            rest.erase(rest.begin() + static_cast<long>(best));
            if (flip) reverse_coedge(e);
            chain.push_back(std::move(e));
        }
        if (total_gap(chain, extent) < total_gap(C, extent)) C = std::move(chain);
    }

    std::vector<geom::Coedge> out;
    out.reserve(C.size());
    const std::size_t n = C.size();
    for (std::size_t i = 0; i < n; ++i) {
        out.push_back(C[i]);
        geom::Coedge& cur = out.back();
        geom::Coedge& nxt = C[(i + 1) % n];
        const Eigen::Vector2d a = end_of(cur.curve), b = start_of(nxt.curve);
        const double gap = scaled_gap(a, b, extent);
        if (gap == 0) continue;
        if (gap <= kSnapGapRelative && (clamped_end(cur.curve, false) || clamped_end(nxt.curve, true))) {
            if (clamped_end(cur.curve, false)) {
                cur.curve = with_end(cur.curve, false, b);
            } else {
                const geom::NurbsCurve2d moved = with_end(nxt.curve, true, a);
                nxt.curve = moved;
                if (i + 1 == n) out.front().curve = moved;
            }
            continue;
        }
        // Bridge with a straight coedge; quiet when both ends are the same
        // surface point (a pole or a collapsed edge).
        geom::Coedge bridge;
        bridge.curve = geom::line_segment(a, b, 0.0, 1.0);
        const double d3 = (surface.evaluate(std::clamp(a.x(), u0, u1), std::clamp(a.y(), v0, v1)) -
                           surface.evaluate(std::clamp(b.x(), u0, u1), std::clamp(b.y(), v0, v1)))
                              .norm();
        if (d3 > model_tolerance && warnings) {
            warnings->push_back(label + ": gap of " + std::to_string(d3) + " between coedges " +
                                std::to_string(i + 1) + " and " + std::to_string((i + 1) % n + 1) +
                                " bridged with a line");
        }
        out.push_back(std::move(bridge));
    }
    C = std::move(out);
    return true;
}

double signed_area(const geom::Loop& loop) {
    std::vector<Eigen::Vector2d> poly;
    for (const geom::Coedge& e : loop.coedges) {
        const auto [a, b] = e.curve.domain();
        for (int k = 0; k < kAreaSamples; ++k) poly.push_back(e.curve.evaluate(a + (b - a) * k / kAreaSamples));
    }
    double area = 0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const Eigen::Vector2d& p = poly[i];
        const Eigen::Vector2d& q = poly[(i + 1) % poly.size()];
        area += p.x() * q.y() - q.x() * p.y();
    }
    return 0.5 * area;
}

namespace {

Eigen::AlignedBox2d loop_box(const geom::Loop& loop) {
    Eigen::AlignedBox2d box;
    for (const geom::Coedge& e : loop.coedges) {
        const auto [a, b] = e.curve.domain();
        for (int k = 0; k <= kAreaSamples; ++k) box.extend(e.curve.evaluate(a + (b - a) * k / kAreaSamples));
    }
    return box;
}

// Box of the loop's control points: holds the whole loop (convex hull property),
// where loop_box's samples may miss a curve's extremes.
Eigen::AlignedBox2d control_box(const geom::Loop& loop) {
    Eigen::AlignedBox2d box;
    for (const geom::Coedge& e : loop.coedges)
        for (const Eigen::Vector2d& p : e.curve.points()) box.extend(p);
    return box;
}

}  // namespace

std::size_t enclosing_loop(const std::vector<geom::Loop>& loops, std::size_t declared) {
    if (declared >= loops.size()) return declared;
    const Eigen::AlignedBox2d inner = loop_box(loops[declared]);
    std::size_t best = declared;
    double best_area = std::fabs(signed_area(loops[declared]));
    for (std::size_t i = 0; i < loops.size(); ++i) {
        const double area = std::fabs(signed_area(loops[i]));
        // Samples of the declared loop inside the candidate's control box: loops that
        // touch (a hole through the outer loop's vertex) still count as enclosed.
        if (i != declared && area > best_area && control_box(loops[i]).contains(inner)) {
            best = i;
            best_area = area;
        }
    }
    return best;
}

void orient_loop(geom::Loop& loop, bool counter_clockwise) {
    const double area = signed_area(loop);
    if ((area > 0) == counter_clockwise || area == 0) return;
    std::reverse(loop.coedges.begin(), loop.coedges.end());
    for (geom::Coedge& e : loop.coedges) reverse_coedge(e);
}

}  // namespace trimkit::io
