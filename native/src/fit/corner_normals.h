// Tangent planes along a boundary from its corners alone, for edges without a G1
// neighbour (the curve-mesh idea of [Muraki]'s [8]): at a corner where two edges
// meet at an angle, both edge tangents lie in the surface's tangent plane, so
// n = t_in x t_out is its normal. Between two such corners the normal is
// interpolated by boundary length (normalised), which is exact for planes and
// for a cylinder's arcs and rulings. Re-derived; the paper gives no formula.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "fit/boundary_samples.h"

namespace trimkit::fit {

// Corners whose edges meet at less than this sine are smooth and carry no normal.
constexpr double kCornerSine = 0.2;

// Per sample: the interpolated unit normal oriented like `up`, or none when the
// sample's loop has no corner with an angle (a circle).
std::vector<std::optional<Eigen::Vector3d>> corner_normals(const std::vector<BoundarySample>& samples,
                                                           const Eigen::Vector3d& up);

}  // namespace trimkit::fit
