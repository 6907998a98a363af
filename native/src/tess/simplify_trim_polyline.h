// Line simplification of an approximated trim curve with the error budget left
// over by the approximation ([Balazs] Sec. 5.1: approximate with γ·tol, simplify
// with (1 - γ)·tol). Douglas-Peucker on the original points: a point may go when
// every original point between the kept neighbours stays within the budget of the
// new segment, both in 3D and, through the surface, in (u,v).
#pragma once

#include "tess/trim_polyline.h"

namespace trimkit::tess {

// Removes interior points of `polyline` (first and last are kept). A range of
// original points is replaced by the segment between its ends when, for each
// point X in it, |X.xyz - segment| <= tolerance and
// surface_speed · |X.uv - uv segment| <= tolerance; surface_speed bounds
// sqrt(|S_u|² + |S_v|²) over the curve's region, so S over the new uv segment stays within
// tolerance of S over the old uv polyline (grid lines add points there). Distances
// are measured to the original points, so errors do not accumulate.
void simplify_trim_polyline(TrimPolyline* polyline, double tolerance, double surface_speed);

}  // namespace trimkit::tess
