// Bilinear error of a Bezier patch: how far the two triangles over the patch's
// corners (or any triangulation of points inside its rectangle) can be from the
// surface, and where to split the patch to reduce it. [Balazs] Sec. 5.2, [Kah02].
// Distances are in model units; split parameters are local to the patch, in (0,1).
#pragma once

#include <optional>

#include "tess/bezier_patch.h"
#include "tess/second_derivative_bound.h"
#include "tess/tessellation_options.h"

namespace trimkit::tess {

struct BilinearError {
    double bound = 0.0;      // error bound (kGuaranteed) or estimate (kApproximate)
    bool split_in_u = true;  // direction of the split that reduces it most
    double split = 0.5;      // local split parameter in that direction, in (0,1)
    // The second-derivative bound `bound` came from (rational patches, kGuaranteed), in
    // the patch's local parameters: it holds on every sub-patch too (restricted_bound).
    std::optional<SecondDerivativeBound> derivatives;
};

// [Balazs] Sec. 5.2: e <= e_bilin + 1/4 |P00 - Pm0 - P0n + Pmn| with
// e_bilin = max_ij |P_ij - S~(i/m, j/n)|, S~ the bilinear interpolant of the corners
// (re-derived: S~(a,b) = (1-a)(1-b) P00 + a(1-b) Pm0 + (1-a) b P0n + a b Pmn, a along u).
// kGuaranteed departs from the paper, so the bound holds for every triangulation of
// points of the rectangle that lie on S, not only for the two corner triangles:
//  - e_bilin is replaced by diam{P_ij - S~(i/m,j/n)} (contains 0): S - S~ is a convex
//    combination of these differences, at the triangle vertices and inside alike;
//    the 1/4 |twist| term bounds the linear interpolation of a b on any triangle
//    inside the square (|Cov(a,b)| <= 1/4);
//  - rational patches (weights not all equal) use second_derivative_bound instead
//    (the control net bound above does not hold for them); their split goes across
//    the direction with the larger second derivative, at a multiple of 1/k where k
//    pieces are predicted to meet `tolerance` (the bound falls as 1/k^2), so a
//    uniformly curved patch ends in about as many strips as it needs.
//  - polynomial patches take the smaller of that bound and second_derivative_bound's
//    (both hold; the control net's lags behind on high degrees: on a degree-12 patch of
//    z = u^2 it is 0.273 against the derivatives' 0.25), with the control net's split;
// kApproximate: the paper's approximate measure, P_ij replaced by S(i/m, j/n).
BilinearError bilinear_error(const BezierPatch& patch, ErrorMode mode, double tolerance);

}  // namespace trimkit::tess
