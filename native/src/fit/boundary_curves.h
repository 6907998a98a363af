// The four boundary curves of the fitted surface ([Muraki] Sec. 4.1, Fig. 9 b-c):
// on each reference plane, the intersection points of the cross-boundary lines
// are approximated by a B-spline curve (fit_curve); the corners of adjacent
// curves are averaged and each curve is fitted again through the averaged
// corners, which closes the four-sided region. The curves share the surface's
// degree and control-point count in their direction, so they are its boundary rows.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "fit/fit_rule.h"
#include "fit/outside_samples.h"
#include "geom/nurbs_curve.h"

namespace trimkit::fit {

// A reference plane met by fewer cross-boundary lines than this gets no curve;
// the surface's boundary row there is left free.
constexpr int kMinSidePoints = 4;

struct BoundaryCurves {
    // 0: u = 0, 1: u = 1 (parameter v), 2: v = 0, 3: v = 1 (parameter u).
    std::array<std::optional<geom::NurbsCurve3d>, 4> sides;
};

BoundaryCurves boundary_curves(const OutsideSamples& samples, const FitRule& rule);

// The curves' control points as fixed boundary rows of a count_u x count_v net
// (v fastest); rows without a curve stay empty.
std::vector<std::optional<Eigen::Vector3d>> boundary_rows(const BoundaryCurves& curves, int count_u, int count_v);

}  // namespace trimkit::fit
