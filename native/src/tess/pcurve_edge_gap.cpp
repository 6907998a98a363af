#include "tess/pcurve_edge_gap.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace trimkit::tess {
namespace {

constexpr int kGapSamples = 8, kEdgeSamples = 64;

double point_segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    const Eigen::Vector3d d = b - a;
    const double len2 = d.squaredNorm();
    const double s = len2 > 0.0 ? std::clamp((p - a).dot(d) / len2, 0.0, 1.0) : 0.0;
    return (a + s * d - p).norm();
}

constexpr int kFootIterations = 20;

// Distance from p to the edge curve, from the parameter s (a sample's) by Newton's
// method on f(s) = (C(s) - p)·C'(s), f' = |C'|² + (C - p)·C''; the least distance seen.
double distance_to_curve(const geom::NurbsCurve3d& edge, const Eigen::Vector3d& p, double s) {
    const auto [e0, e1] = edge.domain();
    double best = (edge.evaluate(s) - p).norm();
    for (int it = 0; it < kFootIterations; ++it) {
        const std::vector<Eigen::Vector3d> d = edge.derivatives(s, 2);
        const Eigen::Vector3d r = d[0] - p;
        best = std::min(best, r.norm());
        const double f = r.dot(d[1]), df = d[1].squaredNorm() + r.dot(d[2]);
        if (!(df > 0.0)) break;
        const double next = std::clamp(s - f / df, e0, e1);
        if (next == s) break;
        s = next;
    }
    return std::min(best, (edge.evaluate(s) - p).norm());
}

}  // namespace

double pcurve_edge_gap_fine(const geom::NurbsSurface& S, const geom::NurbsCurve2d& c,
                            const geom::NurbsCurve3d& edge) {
    const auto [e0, e1] = edge.domain();
    std::vector<Eigen::Vector3d> samples(kEdgeSamples + 1);
    for (int k = 0; k <= kEdgeSamples; ++k) samples[k] = edge.evaluate(e0 + (e1 - e0) * k / kEdgeSamples);
    const auto [t0, t1] = c.domain();
    double gap = 0.0;
    for (int k = 0; k <= kFineGapSamples; ++k) {
        const Eigen::Vector2d uv = c.evaluate(t0 + (t1 - t0) * k / kFineGapSamples);
        const Eigen::Vector3d p = S.evaluate(uv.x(), uv.y());
        int nearest = 0;
        for (int j = 1; j <= kEdgeSamples; ++j)
            if ((samples[j] - p).squaredNorm() < (samples[nearest] - p).squaredNorm()) nearest = j;
        gap = std::max(gap, distance_to_curve(edge, p, e0 + (e1 - e0) * nearest / kEdgeSamples));
    }
    return gap;
}

double pcurve_edge_gap(const geom::NurbsSurface& S, const geom::NurbsCurve2d& c, const geom::NurbsCurve3d& edge) {
    const auto [e0, e1] = edge.domain();
    std::vector<Eigen::Vector3d> polyline(kEdgeSamples + 1);
    for (int k = 0; k <= kEdgeSamples; ++k) polyline[k] = edge.evaluate(e0 + (e1 - e0) * k / kEdgeSamples);
    const auto [t0, t1] = c.domain();
    double gap = 0.0;
    for (int k = 0; k <= kGapSamples; ++k) {
        const Eigen::Vector2d uv = c.evaluate(t0 + (t1 - t0) * k / kGapSamples);
        const Eigen::Vector3d p = S.evaluate(uv.x(), uv.y());
        double nearest = std::numeric_limits<double>::infinity();
        for (int j = 0; j < kEdgeSamples; ++j)
            nearest = std::min(nearest, point_segment_distance(p, polyline[j], polyline[j + 1]));
        gap = std::max(gap, nearest);
    }
    return gap;
}

}  // namespace trimkit::tess
