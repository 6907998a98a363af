// A B-spline surface widened past its domain by continuing its end spans: inside the
// old domain the shape is unchanged; beyond it each end span's own polynomial (in
// homogeneous coordinates when rational) goes on. Real CAD files trim B-spline faces
// with p-curves that run slightly outside the surface's domain, meaning this
// extension (OCCT and the CAD systems evaluate it so); clamping there would cut
// the face short.
#pragma once

#include "geom/nurbs_surface.h"

namespace trimkit::geom {

// S on [min(u0, U_start), max(u1, U_end)] x [min(v0, V_start), max(v1, V_end)].
// Method (re-derived from [PT] Sec. 5.2 and de Casteljau's algorithm): the knot next
// to each widened end is raised to multiplicity p so that the end span is a Bézier
// piece; de Casteljau's scheme at the widened end's local parameter s > 1 (or < 0)
// gives the control polygon of the same polynomial over the widened span.
// Throws InvalidInput for a non-finite bound, or NumericalFailure when a rational
// span's weights would reach 0 on the widened part (it cannot be continued).
NurbsSurface extrapolated_surface(const NurbsSurface& S, double u0, double u1, double v0, double v1);

}  // namespace trimkit::geom
