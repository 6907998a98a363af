// Conservative sup-norm bounds on the derivatives of a NURBS surface S(u,v) and a
// 2D trim curve c(t) = (u(t), v(t)), from the control points of their hodograph
// (derivative) nets: every value of a derivative lies in the convex hull of its
// Bézier control points. These are the M's of [Yang] eq. 2, 7-9. Derivatives are
// with respect to the objects' own parameters (not normalised to [0, 1]).
#pragma once

#include "geom/nurbs_curve.h"
#include "geom/nurbs_surface.h"

namespace trimkit::tess {

// Upper bounds over the whole domain of S on |S_u|, |S_v|, |S_uu|, |S_uv|, |S_vv|
// (Euclidean norms). [Yang] Sec. 2.1 (M^u, M^v, M^uu, M^uv, M^vv).
struct SurfaceDerivativeBounds {
    double Mu = 0.0, Mv = 0.0, Muu = 0.0, Muv = 0.0, Mvv = 0.0;
};

// Rational S: with H = w·(S - O) (homogeneous, polynomial on each Bézier patch, O
// the centre of the control box) the quotient rule gives, re-derived,
//   S_u  = (H_u - (S-O) w_u) / w,
//   S_uu = (H_uu - 2 S_u w_u - (S-O) w_uu) / w,
//   S_uv = (H_uv - S_u w_v - S_v w_u - (S-O) w_uv) / w,
// bounded term by term with |S-O| <= max |P_ij - O| and w >= min w_ij.
SurfaceDerivativeBounds surface_derivative_bounds(const geom::NurbsSurface& S);

// The same restricted to the part of the domain inside `region` (clipped to the
// domain; a range thinner than kMinRegionRelative of the domain is widened to it),
// via S.sub_surface: tighter than the whole surface's bounds.
constexpr double kMinRegionRelative = 1e-6;
SurfaceDerivativeBounds surface_derivative_bounds(const geom::NurbsSurface& S,
                                                  const Eigen::AlignedBox2d& region);

// True when S is C^1 across every interior knot line strictly inside `region`
// (multiplicity m <= degree - 1, [PT] Sec. 2.2: C^(p-m) there). Only then do the
// second-derivative bounds above bound the linear interpolation error of S along a
// segment that crosses such a line (at a C^0 crease S_uu etc. are unbounded).
bool is_c1_inside(const geom::NurbsSurface& S, const Eigen::AlignedBox2d& region);

// Upper bounds over the whole domain of c on |u'(t)|, |v'(t)| and |c''(t)|.
// [Yang] eq. 7-8 (M^t_u, M^t_v, M^tt). Rational c: the same quotient rule as above.
struct CurveDerivativeBounds {
    double Mtu = 0.0, Mtv = 0.0, Mtt = 0.0;
};

CurveDerivativeBounds curve_derivative_bounds(const geom::NurbsCurve2d& c);

}  // namespace trimkit::tess
