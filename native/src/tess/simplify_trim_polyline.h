// Line simplification of an approximated trim curve with the error budget left
// over by the approximation ([Balazs] Sec. 5.1: approximate with γ·tol, simplify
// with (1 - γ)·tol). Douglas-Peucker on the original points: a point may go when
// every original point between the kept neighbours stays within the budget of the
// new segment, both in 3D and, through the surface, in (u,v).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "geom/nurbs_surface.h"
#include "mesh/deadline.h"
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

// The control points that hold one segment of an approximated trim curve: the lifted
// piece's (projected to 3D) and c's over the same parameters (in (u,v)). With positive
// weights the exact curve lies in their convex hulls. Empty: not known (no exact lift).
struct SegmentHull {
    std::vector<Eigen::Vector3d> xyz;
    std::vector<Eigen::Vector2d> uv;
};

// Douglas-Peucker against the exact curve instead of its points, with the whole
// tolerance: a range of segments becomes the chord between its ends when every hull
// point of the range lies within e3 of the 3D chord and within e2 of the (u,v) chord,
// e3 + surface_speed e2 <= tolerance. The distance to a segment is convex, so its
// largest value over a hull is at a control point; the curve runs from one end of the
// chord to the other, so every chord point is as near the curve (the bound of
// approximate_trim_curve's kBezier3d, over several pieces). This is what lets a chord
// cross the surface's knot lines, where the lifted pieces end (a flat strip of many
// spans). Not across a C^0 knot line of S (is_c1_inside over the chord's (u,v) box):
// kd_subdivision's crossing offsets need S to be C^1 along a segment.
// hulls[k]: segment k, from point k to k + 1; segments without a hull stay as they are.
// `deadline`: checked per range and per hull tested (a curve of many points whose
// ranges split one point at a time takes the square of its points); throws
// mesh::DeadlineExceeded once it has passed.
void simplify_trim_polyline(TrimPolyline* polyline, const std::vector<SegmentHull>& hulls,
                            const geom::NurbsSurface& S, double tolerance, double surface_speed,
                            mesh::Deadline* deadline = nullptr);

}  // namespace trimkit::tess
