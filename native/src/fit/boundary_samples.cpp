#include "fit/boundary_samples.h"

#include <algorithm>
#include <string>

#include "geom/error.h"

namespace trimkit::fit {

namespace {

// Fraction of the domain for the chord that stands in for a vanishing derivative
// (collapsed control points at a curve's end): the direction the curve leaves in.
constexpr double kChordStep = 1e-4;

// C'(t) normalised, or the unit chord towards a nearby point where C'(t) = 0;
// zero when neither has a direction.
Eigen::Vector3d unit_tangent(const geom::NurbsCurve3d& curve, double t) {
    const Eigen::Vector3d d = curve.derivatives(t, 1)[1];
    if (d.norm() > 0) return d.normalized();
    const auto [a, b] = curve.domain();
    const double h = kChordStep * (b - a);
    const Eigen::Vector3d chord = curve.evaluate(std::min(b, t + h)) - curve.evaluate(std::max(a, t - h));
    return chord.norm() > 0 ? Eigen::Vector3d(chord.normalized()) : Eigen::Vector3d::Zero();
}

}  // namespace

Eigen::Vector3d coedge_point(const std::vector<geom::Edge>& edges, const geom::Coedge& coedge, double s) {
    const geom::NurbsCurve3d& curve = *edges[coedge.edge].curve;
    const auto [a, b] = curve.domain();
    return curve.evaluate(coedge.edge_reversed ? b - s * (b - a) : a + s * (b - a));
}

std::vector<BoundarySample> boundary_samples(const geom::Face& face, const std::vector<geom::Edge>& edges,
                                             int per_coedge) {
    std::vector<BoundarySample> samples;
    for (int l = 0; l < static_cast<int>(face.loops.size()); ++l)
        for (int c = 0; c < static_cast<int>(face.loops[l].coedges.size()); ++c) {
            const geom::Coedge& coedge = face.loops[l].coedges[c];
            if (coedge.edge < 0 || coedge.edge >= static_cast<int>(edges.size()) || !edges[coedge.edge].curve)
                throw geom::InvalidInput("boundary_samples: loop " + std::to_string(l) + " coedge " +
                                         std::to_string(c) + " has no 3D edge curve");
            const geom::NurbsCurve3d& curve = *edges[coedge.edge].curve;
            const auto [a, b] = curve.domain();
            if (!(curve.control_box().diagonal().norm() > 0)) continue;  // a degenerate edge (a pole): no samples
            const int first = static_cast<int>(samples.size());
            for (int k = 0; k < per_coedge; ++k) {
                const double s = static_cast<double>(k) / per_coedge;
                const double t = coedge.edge_reversed ? b - s * (b - a) : a + s * (b - a);
                Eigen::Vector3d tangent = unit_tangent(curve, t);
                if (coedge.edge_reversed) tangent = -tangent;
                if (!(tangent.norm() > 0))
                    throw geom::NumericalFailure("boundary_samples: edge " + std::to_string(coedge.edge) +
                                                 " has no tangent direction at t = " + geom::format_value(t));
                samples.push_back({curve.evaluate(t), tangent, l, c, Eigen::Vector3d::Zero()});
            }
            const Eigen::Vector3d end = unit_tangent(curve, coedge.edge_reversed ? a : b);
            samples[first].end_tangent = coedge.edge_reversed ? Eigen::Vector3d(-end) : end;
        }
    return samples;
}

}  // namespace trimkit::fit
