// The area a face's mesh gains or loses because its boundary runs along the 3D
// chords of its trim polylines instead of the trim curves S(c(t)). Each chord and
// the curve over it bound a segment of about 2/3 chord x sagitta (a parabola's),
// the sagitta measured in 3D from the chord's line, and counted on the region's
// side: lost where the curve bulges away from the region, gained where it bulges
// into it. A p-curve straight in (u,v) can still bow in 3D (OCC26308-Face.stp: an
// iso-line of a surface whose parameter speed varies 13x, one chord 88 mm long),
// so this is not the uv polygon's error. tessellate_model makes the trims of a
// model finer when its chords lose more of its area than a check allows.
#pragma once

#include "geom/nurbs_curve.h"
#include "geom/nurbs_surface.h"
#include "tess/trim_polyline.h"

namespace trimkit::tess {

// Signed area (model units²) the chords of `polyline` (points on coedge curve c of
// surface S, with their t) lose against S(c(t)): positive when the mesh is smaller.
// Each chord's sagitta is the largest distance from its line of S(c(t)) at t = 1/4,
// 1/2, 3/4 of its parameter span, within the tangent plane there (the bulge along the
// normal is the cells' sag: cell_area_loss.h); the side is read against Su x Sv.
// region_left: the face's region lies to the left of the polyline in (u,v).
double trim_area_loss(const geom::NurbsSurface& S, const geom::NurbsCurve2d& c, const TrimPolyline& polyline,
                      bool region_left);

// True if the face's region lies to the left of `loop` (joined, in traversal order):
// an outer loop running counter-clockwise in (u,v), or a hole clockwise.
bool region_left_of(const TrimPolygon& loop, bool outer);

}  // namespace trimkit::tess
