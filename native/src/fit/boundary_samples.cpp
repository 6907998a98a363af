#include "fit/boundary_samples.h"

#include <string>

#include "geom/error.h"

namespace trimkit::fit {

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
            for (int k = 0; k < per_coedge; ++k) {
                const double s = static_cast<double>(k) / per_coedge;
                const double t = coedge.edge_reversed ? b - s * (b - a) : a + s * (b - a);
                const auto d = curve.derivatives(t, 1);
                Eigen::Vector3d tangent = coedge.edge_reversed ? Eigen::Vector3d(-d[1]) : Eigen::Vector3d(d[1]);
                if (!(tangent.norm() > 0))
                    throw geom::NumericalFailure("boundary_samples: edge " + std::to_string(coedge.edge) +
                                                 " has a zero tangent at t = " + geom::format_value(t));
                samples.push_back({d[0], tangent.normalized(), l, c, Eigen::Vector3d::Zero()});
                if (k == 0) {
                    const auto e = curve.derivatives(coedge.edge_reversed ? a : b, 1);
                    const Eigen::Vector3d end = coedge.edge_reversed ? Eigen::Vector3d(-e[1]) : Eigen::Vector3d(e[1]);
                    if (end.norm() > 0) samples.back().end_tangent = end.normalized();
                }
            }
        }
    return samples;
}

}  // namespace trimkit::fit
