// A surface closed in one parameter direction, extended to cover a parameter
// range past its domain, for trim loops that run across the seam (a loop on
// u in [-π/2, π/2] of a cylinder on u in [0, 2π]). Closed: the first and last
// control-point rows across that direction coincide and their weights agree up to
// one factor, so the clamped surface's two boundary curves are the same curve
// (C0 closure; end derivatives need not match). The extension joins copies of the
// surface whose knots are shifted by the period L = domain length, so S(u + L) =
// S(u) is the same point: every point of the result lies on the original surface.
// direction: 0 for u, 1 for v.
#pragma once

#include "geom/nurbs_surface.h"

namespace trimkit::geom {

// True if s is closed in `direction` (boundary rows within `tolerance`, model
// units, and weights agreeing up to one factor to 1e-9 relative).
bool is_closed_surface(const NurbsSurface& s, int direction, double tolerance);

// s on [a, b] in `direction` (the other direction's domain kept): the domain is
// tiled by period-shifted copies joined at their seams (knot multiplicity p
// there, the earlier copy's boundary row kept), then cut to [a, b] by knot
// insertion (NurbsSurface::sub_surface). [a, b] inside the domain gives the
// plain sub-surface. Throws InvalidInput if s is not closed within `tolerance`,
// a >= b, or [a, b] needs more than kMaxPeriods copies or starts more than
// kMaxPeriodsAway periods from the domain.
NurbsSurface extend_closed_surface(const NurbsSurface& s, int direction, double a, double b,
                                   double tolerance);

// Copies joined at most: trim loops wind around a closed surface once, and
// a range spanning a few periods is already a broken file.
constexpr int kMaxPeriods = 4;
// ... and the range starts within this many periods of the domain.
constexpr int kMaxPeriodsAway = 64;

}  // namespace trimkit::geom
