#include "io/boundary_extent.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace trimkit::io {
namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;

// x brought into [0, 2π).
double turn_angle(double x) {
    double y = std::fmod(x, kTwoPi);
    if (y < 0) y += kTwoPi;
    return y >= kTwoPi ? 0.0 : y;
}

}  // namespace

std::pair<double, double> padded_extent(const std::vector<double>& values, double margin_share) {
    assert(!values.empty() && "padded_extent needs at least one value");
    double lo = values.front(), hi = values.front();
    for (double t : values) {
        lo = std::min(lo, t);
        hi = std::max(hi, t);
    }
    const double m = margin_share * std::max(hi - lo, 1e-9 * (1 + std::fabs(lo) + std::fabs(hi)));
    return {lo - m, hi + m};
}

AngularExtent angular_extent(const std::vector<double>& angles, double margin_share) {
    // Covered arcs [start, start + length], start in [0, 2π): every point, and the
    // step between consecutive points when they are joined.
    std::vector<std::pair<double, double>> arcs;
    arcs.reserve(2 * angles.size());
    for (std::size_t i = 0; i < angles.size(); ++i) {
        const double a = angles[i];
        if (!std::isfinite(a)) continue;
        arcs.emplace_back(turn_angle(a), 0.0);
        if (i + 1 == angles.size() || !std::isfinite(angles[i + 1])) continue;
        const double step = std::remainder(angles[i + 1] - a, kTwoPi);
        if (std::fabs(step) <= kMaxJoinedAngleStep)
            arcs.emplace_back(turn_angle(step >= 0 ? a : a + step), std::fabs(step));
    }
    AngularExtent whole;
    whole.lo = 0;
    whole.hi = kTwoPi;
    whole.full = true;
    if (arcs.empty()) return whole;
    std::sort(arcs.begin(), arcs.end());
    // Sweep once round: the largest gap between the reach so far and the next start,
    // and the gap from the last reach round to the first start.
    double reach = arcs.front().first + arcs.front().second;
    double gap = -1, gap_start = 0, gap_end = 0;
    for (std::size_t i = 1; i < arcs.size(); ++i) {
        if (arcs[i].first - reach > gap) {
            gap = arcs[i].first - reach;
            gap_start = reach;
            gap_end = arcs[i].first;
        }
        reach = std::max(reach, arcs[i].first + arcs[i].second);
    }
    if (arcs.front().first + kTwoPi - reach > gap) {
        gap = arcs.front().first + kTwoPi - reach;
        gap_start = reach;
        gap_end = arcs.front().first + kTwoPi;
    }
    const double sweep = kTwoPi - gap;
    if (gap <= kMinAngularSweep || sweep < kMinAngularSweep) return whole;
    AngularExtent out;
    const double lo = turn_angle(gap_end);
    const double m = std::min(margin_share * sweep, 0.25 * gap);
    out.lo = lo - m;
    out.hi = lo + sweep + m;
    (void)gap_start;
    return out;
}

}  // namespace trimkit::io
