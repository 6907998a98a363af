#include "tess/simplify_trim_polyline.h"

#include <algorithm>
#include <vector>

namespace trimkit::tess {

namespace {

template <class V>
double segment_distance(const V& x, const V& a, const V& b) {
    const V ab = b - a;
    const double len2 = ab.squaredNorm();
    const double lambda = len2 > 0.0 ? std::clamp((x - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (x - (a + lambda * ab)).norm();
}

}  // namespace

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
            const double d3 = segment_distance(P[k].xyz, P[a].xyz, P[b].xyz);
            const double d2 = surface_speed * segment_distance(P[k].uv, P[a].uv, P[b].uv);
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
    std::vector<PolylinePoint> kept;
    for (int k = 0; k < n; ++k)
        if (keep[k]) kept.push_back(P[k]);
    P = std::move(kept);
}

}  // namespace trimkit::tess
