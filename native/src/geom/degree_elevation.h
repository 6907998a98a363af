// Degree elevation of NURBS curves: the same curve (shape and parameterisation)
// written with degree p + t. Every distinct interior knot's multiplicity grows by
// t, so the continuity there is unchanged. Works on homogeneous points, so
// rational curves are elevated exactly.
#pragma once

#include "geom/nurbs_curve.h"

namespace trimkit::geom {

// The curve c raised from degree p to p + t (t >= 0; t == 0 returns c). An
// unclamped c is first clamped to its domain. [PT] Sec. 5.5, Algorithm A5.9.
// Throws InvalidInput if t < 0 or p + t > kMaxDegree.
template <int Dim>
NurbsCurve<Dim> elevate_degree(const NurbsCurve<Dim>& c, int t);

extern template NurbsCurve<2> elevate_degree(const NurbsCurve<2>&, int);
extern template NurbsCurve<3> elevate_degree(const NurbsCurve<3>&, int);

}  // namespace trimkit::geom
