#include "tess/pcurve_edge_gap.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "geom/segment_distance.h"

namespace trimkit::tess {
namespace {

constexpr int kGapSamples = 8, kEdgeSamples = 64;
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

// The edge curve at kEdgeSamples + 1 equal parameter steps.
std::vector<Eigen::Vector3d> edge_samples(const geom::NurbsCurve3d& edge) {
    const auto [e0, e1] = edge.domain();
    std::vector<Eigen::Vector3d> samples(kEdgeSamples + 1);
    for (int k = 0; k <= kEdgeSamples; ++k) samples[k] = edge.evaluate(e0 + (e1 - e0) * k / kEdgeSamples);
    return samples;
}

// Largest `distance(P)` over P = S(c(t)) at `steps` + 1 equal steps of c's domain.
template <class Distance>
double largest_over_pcurve(const geom::NurbsSurface& S, const geom::NurbsCurve2d& c, int steps,
                           const Distance& distance) {
    const auto [t0, t1] = c.domain();
    double gap = 0.0;
    for (int k = 0; k <= steps; ++k) {
        const Eigen::Vector2d uv = c.evaluate(t0 + (t1 - t0) * k / steps);
        gap = std::max(gap, distance(S.evaluate(uv.x(), uv.y())));
    }
    return gap;
}

}  // namespace

double pcurve_edge_gap_fine(const geom::NurbsSurface& S, const geom::NurbsCurve2d& c,
                            const geom::NurbsCurve3d& edge) {
    const auto domain = edge.domain();
    const double e0 = domain.first, e1 = domain.second;
    const std::vector<Eigen::Vector3d> samples = edge_samples(edge);
    return largest_over_pcurve(S, c, kFineGapSamples, [&](const Eigen::Vector3d& p) {
        int nearest = 0;
        for (int j = 1; j <= kEdgeSamples; ++j)
            if ((samples[j] - p).squaredNorm() < (samples[nearest] - p).squaredNorm()) nearest = j;
        return distance_to_curve(edge, p, e0 + (e1 - e0) * nearest / kEdgeSamples);
    });
}

double pcurve_edge_gap(const geom::NurbsSurface& S, const geom::NurbsCurve2d& c, const geom::NurbsCurve3d& edge) {
    const std::vector<Eigen::Vector3d> polyline = edge_samples(edge);
    return largest_over_pcurve(S, c, kGapSamples, [&](const Eigen::Vector3d& p) {
        double nearest = std::numeric_limits<double>::infinity();
        for (int j = 0; j < kEdgeSamples; ++j)
            nearest = std::min(nearest, geom::segment_distance(p, polyline[j], polyline[j + 1]));
        return nearest;
    });
}

}  // namespace trimkit::tess
