// Error bound of a cell that crosses knot lines: a (u,v) rectangle over several
// knot spans of a surface, meshed as one kd cell instead of one per Bezier patch
// (a long, nearly flat B-spline strip of many spans needs no point at every knot).
#pragma once

#include <Eigen/Geometry>

#include "geom/nurbs_surface.h"

namespace trimkit::tess {

struct BlockError {
    double bound = 0.0;   // the sum below; infinite when S is not C^1 inside the rectangle
    double u_term = 0.0;  // M_uu du^2 / 8, the share that splitting across u reduces
    double v_term = 0.0;  // M_vv dv^2 / 8
};

// Bound on the distance from S, at the same (u,v), of any triangle whose vertices are
// points of S inside `r`, in both directions (the measure of bilinear_error):
//   (M_uu du^2 + 2 M_uv du dv + M_vv dv^2) / 8,
// second_derivative_bound.cpp step 1 (Taylor's integral remainder) in the surface's
// own parameters, with the M's of surface_derivative_bounds over r. The remainder
// needs S to be C^1 inside r (is_c1_inside): across a C^0 knot line the bound is
// infinite.
BlockError block_error(const geom::NurbsSurface& S, const Eigen::AlignedBox2d& r);

}  // namespace trimkit::tess
