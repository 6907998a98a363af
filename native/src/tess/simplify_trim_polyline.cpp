#include "tess/simplify_trim_polyline.h"

#include <algorithm>
#include <limits>
#include <vector>

#include "geom/segment_distance.h"
#include "tess/derivative_bounds.h"

namespace trimkit::tess {

namespace {

// Keeps the points `keep` marks.
void keep_marked(std::vector<PolylinePoint>& P, const std::vector<char>& keep) {
    std::vector<PolylinePoint> kept;
    for (size_t k = 0; k < P.size(); ++k)
        if (keep[k]) kept.push_back(P[k]);
    P = std::move(kept);
}

// (e3 + speed e2) / tolerance over the hulls of segments a .. b-1 against the chord
// from point a to point b; infinite where a segment has no hull.
double hull_ratio(const std::vector<PolylinePoint>& P, const std::vector<SegmentHull>& hulls, int a, int b,
                  double tolerance, double speed, mesh::Deadline* deadline) {
    double e3 = 0.0, e2 = 0.0;
    for (int k = a; k < b; ++k) {
        mesh::check_deadline(deadline, "trim curve simplification");
        if (hulls[k].xyz.empty()) return std::numeric_limits<double>::infinity();
        for (const Eigen::Vector3d& x : hulls[k].xyz) e3 = std::max(e3, geom::segment_distance(x, P[a].xyz, P[b].xyz));
        if (speed > 0.0)
            for (const Eigen::Vector2d& y : hulls[k].uv) e2 = std::max(e2, geom::segment_distance(y, P[a].uv, P[b].uv));
    }
    return (e3 + speed * e2) / tolerance;
}

}  // namespace

void simplify_trim_polyline(TrimPolyline* polyline, const std::vector<SegmentHull>& hulls,
                            const geom::NurbsSurface& S, double tolerance, double surface_speed,
                            mesh::Deadline* deadline) {
    std::vector<PolylinePoint>& P = polyline->points;
    const int n = static_cast<int>(P.size());
    if (n <= 2 || !(tolerance > 0.0) || hulls.size() + 1 != P.size()) return;
    // The points on C^0 knot lines stay (the lifted pieces end there), and the ranges
    // between them are simplified apart.
    std::vector<char> keep(n, 0);
    keep[0] = keep[n - 1] = 1;
    for (int k = 1; k + 1 < n; ++k) {
        Eigen::AlignedBox2d around(P[k - 1].uv);
        around.extend(P[k + 1].uv);
        keep[k] = !is_c1_inside(S, around);
    }
    std::vector<std::pair<int, int>> stack;
    for (int a = 0, b = 1; b < n; ++b)
        if (keep[b]) stack.push_back({a, b}), a = b;
    while (!stack.empty()) {
        const auto [a, b] = stack.back();
        stack.pop_back();
        if (b - a < 2) continue;
        Eigen::AlignedBox2d chord_box(P[a].uv);
        chord_box.extend(P[b].uv);
        if (hull_ratio(P, hulls, a, b, tolerance, surface_speed, deadline) <= 1.0 && is_c1_inside(S, chord_box))
            continue;
        // Split at the point farthest from the chord, as Douglas-Peucker does.
        int worst = (a + b) / 2;
        double worst_distance = 0.0;
        for (int k = a + 1; k < b; ++k) {
            const double d = geom::segment_distance(P[k].xyz, P[a].xyz, P[b].xyz) +
                             surface_speed * geom::segment_distance(P[k].uv, P[a].uv, P[b].uv);
            if (d > worst_distance) worst_distance = d, worst = k;
        }
        keep[worst] = 1;
        stack.push_back({a, worst});
        stack.push_back({worst, b});
    }
    keep_marked(P, keep);
}

void simplify_trim_polyline(TrimPolyline* polyline, double tolerance, double surface_speed) {
    std::vector<PolylinePoint>& P = polyline->points;
    const int n = static_cast<int>(P.size());
    if (n <= 2 || !(tolerance > 0.0)) return;
    std::vector<char> keep(n, 0);
    keep[0] = keep[n - 1] = 1;
    // Iterative Douglas-Peucker: ranges (a, b) whose interior is still undecided.
    std::vector<std::pair<int, int>> stack = {{0, n - 1}};
    while (!stack.empty()) {
        const auto [a, b] = stack.back();
        stack.pop_back();
        if (b - a < 2) continue;
        int worst = -1;
        double worst_ratio = 0.0;
        for (int k = a + 1; k < b; ++k) {
            const double d3 = geom::segment_distance(P[k].xyz, P[a].xyz, P[b].xyz);
            const double d2 = surface_speed * geom::segment_distance(P[k].uv, P[a].uv, P[b].uv);
            const double ratio = std::max(d3, d2) / tolerance;
            if (ratio > worst_ratio) {
                worst_ratio = ratio;
                worst = k;
            }
        }
        if (worst_ratio <= 1.0) continue;
        keep[worst] = 1;
        stack.push_back({a, worst});
        stack.push_back({worst, b});
    }
    keep_marked(P, keep);
}

}  // namespace trimkit::tess
