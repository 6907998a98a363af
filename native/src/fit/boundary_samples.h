// Points along a face's boundary edges ([Muraki] Sec. 4.3, the blue markers of
// Fig. 11 b): each coedge's 3D edge curve sampled in the coedge's traversal
// direction, so the face lies on the left of the tangent seen from its normal.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "geom/model.h"

namespace trimkit::fit {

struct BoundarySample {
    Eigen::Vector3d x;
    Eigen::Vector3d tangent;  // unit, in traversal direction
    int loop = 0, coedge = 0;
    Eigen::Vector3d end_tangent = Eigen::Vector3d::Zero();  // first sample of a coedge: the unit tangent at its end
};

// The point at fraction s in [0, 1] along a coedge's edge curve, in traversal
// direction. Assumes the edge exists and has a curve.
Eigen::Vector3d coedge_point(const std::vector<geom::Edge>& edges, const geom::Coedge& coedge, double s);

// `per_coedge` samples per coedge at equal parameter steps, its end excluded (the
// next coedge starts there). Throws geom::InvalidInput if a coedge has no edge
// with a 3D curve (coedge_edges gives every coedge one) and NumericalFailure if a
// curve has no direction at a sample. A zero derivative (collapsed control points)
// is replaced by the chord's direction; a degenerate edge (one point: a pole) gives
// no samples.
std::vector<BoundarySample> boundary_samples(const geom::Face& face, const std::vector<geom::Edge>& edges,
                                             int per_coedge);

}  // namespace trimkit::fit
