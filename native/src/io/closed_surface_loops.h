// Trim loops on closed surfaces, for the readers' face_loops (IGES and the own STEP
// reader). A surface closed in u or v (geom::is_closed_surface) is periodic there
// with the domain length as period; files trim such surfaces with loops that run
// across the seam (a loop on u in [-π/2, π/2] of a surface of revolution on
// [0, 2π]) or whose coedges continue on the seam's other side. The loops are
// unwrapped (each coedge shifted by whole periods to start where the previous one
// ends) and the surface is extended over them (geom::extend_closed_surface, exact),
// so the face is the region the file means instead of the part of it inside the domain.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "geom/face.h"

namespace trimkit::io {

// Period per direction: 0 where the surface is not closed.
struct SurfacePeriods {
    double u = 0.0, v = 0.0;
    double operator[](int d) const { return d == 0 ? u : v; }
    bool any() const { return u > 0.0 || v > 0.0; }
};

// Closed directions of `s` (boundary rows within `tolerance`, model units).
SurfacePeriods closed_periods(const geom::NurbsSurface& s, double tolerance);

// uv in s's domain: taken modulo the period in closed directions, clamped in the others.
Eigen::Vector2d wrap_into_domain(const geom::NurbsSurface& s, const SurfacePeriods& periods,
                                 Eigen::Vector2d uv);

// Whole periods in direction d from the loop's first start to its last end: 0 when it
// closes in (u,v), else how often it winds around the closed direction (period > 0).
int winding(const geom::Loop& loop, int d, double period);

// Shifts coedges by whole periods so that each starts within half a period of
// where the previous one ends (the first stays, unless it runs by a seam: then the
// one farthest from the seams), except across a joint at a pole of
// `surface` in that direction: every u of a pole is the same point, so a coedge may
// leave it on the other side of the seam (a sphere's seam edge runs up to the pole
// on one side and back down on the other). Returns true if any moved.
bool unwrap_loop(geom::Loop& loop, const geom::NurbsSurface& surface, const SurfacePeriods& periods);

// A loop whose ends lie apart along a pole's iso-line (a degenerate iso-line: both
// ends are the pole's one point) by other than whole periods lacks its edge along the
// pole, which files leave out (SolidWorks IGES: half a spherical cap, from the pole
// along one meridian, round half the parallel and back up the other, its ends half a
// period apart): closed by that edge. Without it the half period read as a winding
// (lround(-0.5) = -1), and close_winding_loop_at_pole took the far side of the
// sphere, 3.4 times the face. Returns true if the loop was closed.
bool close_loop_along_its_pole(geom::Loop& loop, const geom::NurbsSurface& surface, const SurfacePeriods& periods);

// A loop that winds around a closed direction (after unwrap_loop its end lies
// a whole number w of periods from its start) bounds a region only together
// with a full turn along an iso-curve: the tessellator bridges the gap where it
// is, so the gap is moved to the joint whose iso-curve (at the joint's other
// parameter, over one period) is shortest in model space - a pole or the small
// end circle of a cone, not the circle across the face (PRO19800.igs: a half cone
// whose model-space trim rounds the apex). Coedges after that joint are shifted
// by -w periods. Returns the iso-curve's length, or -1 if nothing moved.
double settle_winding(geom::Loop& loop, const geom::NurbsSurface& surface, const SurfacePeriods& periods);

// A band of a closed surface (a cylinder between two circles, a cone's chamfer) may
// be bounded by two loops that each wind once around it, the opposite ways, and no
// seam edge (STEP from Parasolid: one closed circle per loop): neither bounds a region
// alone. Joins the two into one loop (band_loop: the second shifted by whole periods
// to face the first, both bridged across by two straight coedges a period apart, the
// same curve on the surface run each way). Returns true if loops were joined.
bool join_winding_loops(std::vector<geom::Loop>& loops, const SurfacePeriods& periods);

// A cap of a closed surface (a hemisphere, a cone up to its apex) may be bounded by one
// loop winding once around it, the pole marked by a VERTEX_LOOP or not at all (STEP
// from Parasolid: the equator circle alone): it bounds a region only with the pole.
// When exactly one loop winds in a direction d and an end of the other direction is a
// pole, the loop is closed there: a seam line to the pole, the pole's (degenerate) iso
// line back one period, and the seam line back (one curve, run both ways). With a
// pole at both ends (a sphere) the face's side of the loop picks the end: left of it
// in (u,v), right on a `reversed` face. Returns true if a loop was closed.
bool close_winding_loop_at_pole(std::vector<geom::Loop>& loops, const geom::NurbsSurface& surface,
                                const SurfacePeriods& periods, bool reversed);

// The natural outer loop (loops[0]) of a face on a closed surface with holes only (a
// ball drilled three times: STEP gives the holes and no outer bound) runs along the
// seam, which a hole may cross. Per closed direction whose seam a hole crosses, the
// natural loop is moved to the middle of the widest gap between the holes (modulo
// the period) over one period, and the holes by whole periods into it (the surface is
// to be extended over them, cover_loops). Returns true if loops moved.
bool place_natural_seam(std::vector<geom::Loop>& loops, const geom::NurbsSurface& surface,
                        const SurfacePeriods& periods);

// Each loop unwrapped from its own start may sit whole periods away from the loop
// that encloses it on the surface (a hole at u in [0.2, 1.4] beside an outer loop
// unwrapped onto [-2π, 0]). Shifts every loop by whole periods so that the centre
// of its (u,v) box lies in the range of the loop of largest area (the outer loop
// encloses the others, and area does not change with a shift), where such a shift
// exists. Returns true if any moved.
// All loops shifted together by whole periods so that they lie in the surface's
// domain, where one shift does it (a fillet's quarter tube unwrapped onto v in
// [-3pi/2, -pi] on a torus of v in [-pi, pi]): the face is the same, and its surface
// need not be extended past its period (cover_loops). Returns true if they moved.
bool shift_loops_into_domain(std::vector<geom::Loop>& loops, const geom::NurbsSurface& surface,
                             const SurfacePeriods& periods);

bool place_loops_by_largest(std::vector<geom::Loop>& loops, const SurfacePeriods& periods);

// Extends `surface` in its closed directions past each end of its domain that the
// loops (sampled) pass by more than kOutsideDomain of the period, to their
// extreme plus kCoverPadding of the period; the domain is kept and the coedges
// stay as they are (the extension keeps the parameterisation). Returns true if
// the surface changed. Ranges wider than geom::kMaxPeriods periods are left alone.
bool cover_loops(geom::NurbsSurface& surface, const std::vector<geom::Loop>& loops,
                 const SurfacePeriods& periods, double tolerance);

// Overshoot below 1e-6 of a period is rounding: the clamped surface is within
// 1e-6 of the surface's size there.
constexpr double kOutsideDomain = 1e-6;
// The extension reaches this fraction of the period past the loops' sampled
// extreme (a curve between samples may bulge slightly beyond it).
constexpr double kCoverPadding = 1e-4;

}  // namespace trimkit::io
