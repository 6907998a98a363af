// The parameter-space image of a model-space curve on a surface, refined until the
// surface along it follows the curve: trim curves given (or preferred) in model
// space become degree-1 curves in (u,v) through foot points (the surface points
// nearest to the curve, SurfaceProjector::invert), so S(pcurve) - what a
// tessellator puts at the face boundary - stays within a tolerance of them.
// Conventions: the result is parameterised by the curve's own parameter t.
#pragma once

#include "geom/nurbs_curve.h"
#include "geom/surface_projector.h"

namespace trimkit::geom {

// Bisections of one of project_curve's sample intervals, and points overall:
// enough for 1e-6 of a curve's size on CAD surfaces; a point where the foot point
// is not unique (a curve through a cone's apex region) stops there.
constexpr int kMaxBisectionDepth = 10;
constexpr int kMaxProjectedPoints = 20000;

// project_curve's samples, each re-projected from its neighbours and kept where
// that lies nearer to c (near a cone's small end Newton from one side stays
// clamped on the end circle, a wrong branch project_curve follows from the
// curve's start), then each segment bisected (at the parameter midpoint) while
// the surface at the segment's (u,v) midpoint lies more than `tolerance` (model
// units) from the foot point of c there (the nearest of Newton runs from the
// midpoint and both ends), to kMaxBisectionDepth levels. An exact result of
// project_curve (a plane: degree > 1) is returned as is.
// period_u, period_v > 0: the surface is closed in that direction with that
// period (S(u + period_u, v) = S(u, v)); consecutive points are unwrapped there,
// so a curve crossing the seam runs on past the domain instead of jumping back
// across it (extend_closed_surface gives a surface covering it). `max_distance`
// (optional) receives the largest distance between c and S at the points.
NurbsCurve2d project_curve_adaptive(const SurfaceProjector& projector, const NurbsCurve3d& c,
                                    double tolerance, double period_u = 0.0, double period_v = 0.0,
                                    double* max_distance = nullptr);

}  // namespace trimkit::geom
