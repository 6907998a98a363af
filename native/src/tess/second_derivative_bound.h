// Interpolation error bound of a rational Bézier patch from bounds on its second
// derivatives: how far any triangle with vertices on S over the patch's (s,t) square
// [0,1]^2 can be from S at the same (s,t). Local parameters as in BezierPatch;
// derivative bounds are per unit of local parameter, lengths in model units.
// Used by bilinear_error for rational patches, where the control net's bilinear
// deviation is not a bound (the control points are not points of a polynomial S).
#pragma once

#include "tess/bezier_patch.h"

namespace trimkit::tess {

struct SecondDerivativeBound {
    double M_uu = 0.0, M_uv = 0.0, M_vv = 0.0;  // sup |S_ss|, |S_st|, |S_tt| over the patch
    // (M_uu + 2 M_uv + M_vv) / 8: the linear-interpolation error bound (see the .cpp).
    double error() const { return (M_uu + 2.0 * M_uv + M_vv) / 8.0; }
};

// Bounds from the control points of the polynomial numerators of S_s and S_t
// (re-derived; [Balazs] Sec. 5.2 gives only the polynomial control-net bound).
// Infinite when a weight is <= 0 or a value is not finite.
SecondDerivativeBound second_derivative_bound(const BezierPatch& patch);

// A patch's bound M (local parameters) on its sub-patch covering the fractions fu of
// its u range and fv of its v range, in the sub-patch's local parameters: the suprema
// over the sub-patch are at most M's, and d/ds' = fu d/ds.
inline SecondDerivativeBound restricted_bound(const SecondDerivativeBound& M, double fu, double fv) {
    return {M.M_uu * fu * fu, M.M_uv * fu * fv, M.M_vv * fv * fv};
}

}  // namespace trimkit::tess
