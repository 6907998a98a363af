// How far a face's p-curve strays from its edge's 3D curve. Files give edges whose
// faces disagree (bm2_ec_exhaust-A: one face's p-curve image 3.5 mm off the edge
// curve, within the edge's tolerance of 3.68 mm, the other face's on it);
// tessellate_model lets the face that follows the edge best give the edge its
// points, so the shared boundary lies where the file's edge is.
#pragma once

#include "geom/nurbs_curve.h"
#include "geom/nurbs_surface.h"

namespace trimkit::tess {

// Largest distance from S(c(t)), at 9 points of c's domain, to the edge's 3D curve
// sampled as a polyline of 64 chords: a coarse figure (a full circle's chords are
// 0.0012 R off it), enough to choose the face that follows the edge when the other
// strays by a share of T.
double pcurve_edge_gap(const geom::NurbsSurface& S, const geom::NurbsCurve2d& c, const geom::NurbsCurve3d& edge);

// The same measured closely, for a figure worth reporting: S(c(t)) at kFineGapSamples
// + 1 points of c's domain, each to its foot on the edge curve (Newton's method on
// (C(s) - P)·C'(s) = 0 from the nearest of 64 samples of C, clamped to C's domain),
// so a curved edge's chords do not count.
constexpr int kFineGapSamples = 32;
double pcurve_edge_gap_fine(const geom::NurbsSurface& S, const geom::NurbsCurve2d& c,
                            const geom::NurbsCurve3d& edge);

}  // namespace trimkit::tess
