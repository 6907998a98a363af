// Exact rational NURBS forms of analytic curves (lines, circles, ellipses, conic
// arcs) for readers. Each keeps the entity's native parameter where it has one:
// a line's domain is [t0, t1]; a circle's or ellipse's domain is [θ0, θ1] with
// the NURBS parameter equal to the (eccentric) angle at every knot, see
// ArcParameterMap for the exact map in between.
#pragma once

#include <Eigen/Core>

#include "geom/nurbs_curve.h"

namespace trimkit::geom {

// Relative tolerance for geometric degeneracy tests (parallel axes, collinear or
// non-coplanar conic data): sines of angles below it count as zero. Far above
// rounding (1e-16) and below what a CAD file would mean as a real angle.
constexpr double kAnalyticTolerance = 1e-9;

// ---- Lines --------------------------------------------------------------------

// The straight segment P0 -> P1 as a degree-1 curve on [t0, t1] (t0 < t1).
// A zero-length segment is allowed (it is a valid, degenerate NURBS curve).
NurbsCurve3d line_segment(const Eigen::Vector3d& P0, const Eigen::Vector3d& P1,
                          double t0 = 0.0, double t1 = 1.0);
NurbsCurve2d line_segment(const Eigen::Vector2d& P0, const Eigen::Vector2d& P1,
                          double t0 = 0.0, double t1 = 1.0);

// ---- Circles and ellipses -------------------------------------------------------

// C(θ) = center + radius (cos θ X + sin θ Y) for θ from θ0 to θ1, where X is
// x_axis normalised and Y the unit part of y_axis orthogonal to X (y_axis only
// fixes the plane and the sense of rotation). Degree 2, ArcParameterMap(θ0, θ1)
// segments; C(map.to_nurbs(θ)) is exactly the point at angle θ.
// [PT] Algorithm A7.1 with segment boundaries at the knots.
// Throws InvalidInput if radius <= 0, an axis is zero or the axes are parallel,
// a value is non-finite, or the sweep is empty or above 2π.
NurbsCurve3d circular_arc(const Eigen::Vector3d& center, const Eigen::Vector3d& x_axis,
                          const Eigen::Vector3d& y_axis, double radius, double theta0,
                          double theta1);

// C(θ) = center + a cos θ X + b sin θ Y (θ = eccentric angle), X, Y as for
// circular_arc; same knots and parameter map as circular_arc. a, b > 0.
NurbsCurve3d ellipse_arc(const Eigen::Vector3d& center, const Eigen::Vector3d& x_axis,
                         const Eigen::Vector3d& y_axis, double a, double b, double theta0,
                         double theta1);

// ---- General conic arcs -----------------------------------------------------------

// Kept single: conic arcs whose tangent turns by more than this (radians) are
// split in two, so middle weights stay well away from 0 (a 180° arc has w = 0).
constexpr double kMaxSingleArcTurn = 0.75 * 3.14159265358979323846;

// The conic arc from P0 (tangent direction T0) to P2 (arriving with tangent
// direction T2) of the unique conic through P0, P2 with those tangents that also
// passes through P_on (anywhere on the conic, e.g. the middle of an IGES 104
// parabola or hyperbola arc). One rational quadratic Bézier segment in standard
// form (end weights 1), or two joined at the arc's extreme point from the chord
// when the arc turns by more than kMaxSingleArcTurn; domain [0, 1].
// [PT] Sec. 7.3, Algorithms A7.2/A7.3 (middle weight from the shoulder point,
// w = s / (1 - s)); the conic is the member of the pencil L0·L2 - κ·M² = 0
// through P_on (L0, L2 the tangent lines, M the chord line), re-derived.
// Throws InvalidInput if the data are not coplanar, degenerate (collinear, zero
// tangents, P_on on a tangent line or the chord line) or admit no arc from P0 to
// P2 leaving along T0 (e.g. an arc through the point at infinity of a hyperbola).
NurbsCurve3d rational_quadratic_arc(const Eigen::Vector3d& P0, const Eigen::Vector3d& T0,
                                    const Eigen::Vector3d& P2, const Eigen::Vector3d& T2,
                                    const Eigen::Vector3d& P_on);

// ---- Dimension changes ---------------------------------------------------------------

// The curve with z dropped (for parameter-space curves stored as 3D entities);
// knots and weights unchanged. z is ignored, not checked.
NurbsCurve2d to_2d(const NurbsCurve3d& c);
// The curve in the plane z = `z`; knots and weights unchanged.
NurbsCurve3d to_3d(const NurbsCurve2d& c, double z = 0.0);

}  // namespace trimkit::geom
