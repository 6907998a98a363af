// LocalFrame: the local coordinate system of a face's boundary and its reference
// planes ([Muraki] Sec. 4.1, Fig. 8 b; the frame of [8]). Origin at the boundary's
// centroid, e1 and e2 its principal directions (covariance of the boundary
// samples, weighted by their spacing), n = e1 x e2 oriented so that the outer loop
// runs counter-clockwise about n. The four reference planes x = x0, x = x1,
// y = y0, y = y1 (x = e1·(p - origin), y = e2·(p - origin)) enclose the boundary's
// projection with a margin; the fitted surface's (u, v) is (x, y) mapped to [0, 1]².
// Departure: the paper's frame comes from the edge sequence [8]; principal axes
// are another affine-covariant choice that needs nothing but the samples.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "fit/boundary_samples.h"

namespace trimkit::fit {

struct LocalFrame {
    Eigen::Vector3d origin, e1, e2, n;
    double x0 = 0, x1 = 1, y0 = 0, y1 = 1;

    Eigen::Vector2d plane(const Eigen::Vector3d& p) const;  // (x, y)
    Eigen::Vector2d uv(const Eigen::Vector3d& p) const;     // (x, y) mapped to [0, 1]² (not clamped)
};

// Margin of the reference rectangle beyond the boundary's projection, as a
// fraction of its larger side: room for the tangent-plane samples outside the
// region (Sec. 4.3) without reaching far from the boundary.
constexpr double kReferenceMargin = 0.1;

// Throws geom::NumericalFailure when the boundary spans less than a plane (all
// samples on a line) or `outer_loop` has no samples.
LocalFrame local_frame(const std::vector<BoundarySample>& samples, int outer_loop);

}  // namespace trimkit::fit
