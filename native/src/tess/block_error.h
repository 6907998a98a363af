// Error bound of a cell that crosses knot lines: a (u,v) rectangle over several
// knot spans of a surface, meshed as one kd cell instead of one per Bezier patch
// (a long, nearly flat B-spline strip of many spans needs no point at every knot).
#pragma once

#include "tess/second_derivative_bound.h"

namespace trimkit::tess {

struct BlockError {
    double bound = 0.0;   // the sum below
    double u_term = 0.0;  // M_uu du^2 / 8, the share that splitting across u reduces
    double v_term = 0.0;  // M_vv dv^2 / 8
};

// Bound on the distance from S, at the same (u,v), of any triangle whose vertices are
// points of S inside a du x dv rectangle, in both directions (the measure of
// bilinear_error):
//   (M_uu du^2 + 2 M_uv du dv + M_vv dv^2) / 8,
// second_derivative_bound.cpp step 1 (Taylor's integral remainder) in the surface's
// own parameters, `M` bounding S's second derivatives over the rectangle in those
// parameters (the largest of its Bezier patches' bounds, each divided by the patch's
// widths: S_uu = S_ss / (u1 - u0)^2). The remainder needs S to be C^1 inside the
// rectangle (derivative_bounds.h, is_c1_inside): across a C^0 knot line it does not
// hold, and the caller must not use it there.
BlockError block_error(const SecondDerivativeBound& M, double du, double dv);

// A patch's bound (local parameters, per unit of s and t) in the surface's own
// parameters over its widths du x dv.
SecondDerivativeBound in_surface_parameters(const SecondDerivativeBound& local, double du, double dv);

}  // namespace trimkit::tess
