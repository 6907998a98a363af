// The box of a 2D NURBS curve's points, tight to a tolerance: the control hull of each
// Bézier segment (which holds the segment where the weights are positive), split at
// the middle until it adds no more than the tolerance to the box the segments' end
// points make. For the (u,v) range of trim curves, where a control-point box is too
// loose and OCCT's BndLib_Add2dCurve::AddOptimal (a particle-swarm search per curve)
// took 40 % of a .brep file's reading.
#pragma once

#include <Eigen/Geometry>

#include "geom/nurbs_curve.h"

namespace trimkit::geom {

// Every point of c lies within `tolerance` of the box, and the box exceeds the points
// by at most `tolerance` per side (by a segment's hull where it splits 30 times).
// Throws InvalidInput for a weight <= 0.
Eigen::AlignedBox2d curve_box(const NurbsCurve2d& c, double tolerance);

}  // namespace trimkit::geom
