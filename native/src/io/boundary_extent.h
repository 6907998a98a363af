// The part of an unbounded or periodic surface's parameter range that a face's
// boundary covers, from the boundary's points expressed in one of the surface's own
// parameters (a length along an axis, or an angle). Readers size planes, cylinders,
// cones, extrusions, ... with these before building their NURBS patch.
#pragma once

#include <utility>
#include <vector>

namespace trimkit::io {

// [min, max] of `values` widened on each side by margin_share of its length, and by
// at least 1e-9 (1 + |min| + |max|) so a single value still gives a non-empty range.
// `values` must not be empty.
std::pair<double, double> padded_extent(const std::vector<double>& values, double margin_share);

// Consecutive boundary points whose angles differ by at most this (radians) are taken
// as joined along the boundary, so the arc between them is covered. A full circle
// sampled with 16 points steps by 24 degrees; points of different loops or edges
// listed one after the other rarely fall this close unless the arc between them is
// covered anyway.
constexpr double kMaxJoinedAngleStep = 0.25 * 3.14159265358979323846;
// A boundary covering less than this sweep (radians), or leaving no uncovered arc
// wider than it, is taken to go all the way round: a face's angular extent is never a
// point, but a full turn's boundary may be only the vertices on its seam; and a gap
// this narrow is rounding where a boundary closes on itself.
constexpr double kMinAngularSweep = 1e-6;

struct AngularExtent {
    double lo = 0, hi = 0;  // lo < hi <= lo + 2π; lo in [-2π, 2π)
    bool full = false;      // a whole turn [0, 2π]
};

// The angular range covered by boundary points whose angles (any turn; NaN: no
// angle, e.g. a point on the axis) are given in boundary order: the circle minus the
// largest arc no point or joined pair of points covers, widened on each side by
// margin_share of its sweep (by at most a quarter of that uncovered arc). A boundary
// leaving no uncovered arc (up to kMinAngularSweep), or covering less than that, is a whole turn,
// returned as [0, 2π] (seam at angle 0, where CAD systems put the seams of periodic
// surfaces). Only the whole-turn answer for empty `angles`.
AngularExtent angular_extent(const std::vector<double>& angles, double margin_share);

}  // namespace trimkit::io
