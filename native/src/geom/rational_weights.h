// Validation of the weights of a rational curve or surface, shared by NurbsCurve
// and NurbsSurface. Weights are per control point, in the points' order.
#pragma once

#include <string>
#include <vector>

namespace trimkit::geom {

// Throws InvalidInput naming `owner` and the index when a weight is not finite or
// not > 0. Returns whether any weight differs from 1 (the curve or surface is
// rational); an empty vector is valid and not rational.
bool validate_rational_weights(const std::vector<double>& weights, const std::string& owner);

}  // namespace trimkit::geom
