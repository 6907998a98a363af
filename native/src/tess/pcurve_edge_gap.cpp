#include "tess/pcurve_edge_gap.h"

#include <algorithm>
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

}  // namespace

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
