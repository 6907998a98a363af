#include "fit/outside_samples.h"

#include <algorithm>
#include <cmath>

namespace trimkit::fit {
namespace {

// Line length to the first reference plane met, and which one.
std::pair<double, int> exit_length(const Eigen::Vector2d& q, const Eigen::Vector2d& d, const LocalFrame& f) {
    double best = 1e300;
    int side = -1;
    const auto consider = [&](double s, int which) {
        if (s > 0 && s < best) best = s, side = which;
    };
    if (d.x() < 0) consider((f.x0 - q.x()) / d.x(), 0);
    if (d.x() > 0) consider((f.x1 - q.x()) / d.x(), 1);
    if (d.y() < 0) consider((f.y0 - q.y()) / d.y(), 2);
    if (d.y() > 0) consider((f.y1 - q.y()) / d.y(), 3);
    return {best, side};
}

}  // namespace

OutsideSamples outside_samples(const std::vector<BoundarySample>& samples, const std::vector<Eigen::Vector3d>& normals,
                               const LocalFrame& frame, const LoopPolygons& region) {
    OutsideSamples out;
    for (std::size_t k = 0; k < samples.size(); ++k) {
        const Eigen::Vector3d d = samples[k].tangent.cross(normals[k]).normalized();
        const Eigen::Vector2d q = frame.plane(samples[k].x);
        const Eigen::Vector2d dq(frame.e1.dot(d), frame.e2.dot(d));
        if (!(dq.norm() >= kMinPlanarDirection)) continue;
        auto [length, side] = exit_length(q, dq, frame);
        if (side < 0) continue;
        for (int i = 1; i <= kEntryChecks; ++i)
            if (region.contains(q + dq * (length * i / kEntryChecks))) {
                length *= 0.5 * (i - 1) / kEntryChecks;
                side = -1;
                break;
            }
        if (!(length > 0)) continue;
        for (int i = 1; i <= kLineSamples; ++i) {
            const Eigen::Vector3d x = samples[k].x + d * (length * i / kLineSamples);
            const Eigen::Vector2d uv = frame.uv(x).cwiseMax(0.0).cwiseMin(1.0);
            out.points.push_back({uv, x, 1.0});
            if (i == kLineSamples && side >= 0) out.sides[side].push_back({side < 2 ? uv.y() : uv.x(), x});
        }
    }
    return out;
}

}  // namespace trimkit::fit
