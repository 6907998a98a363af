// Lifting a 2D trim curve c(t) in a face's (u,v) domain to exact 3D Bézier curves
// of S(c(t)). [Balazs] Sec. 4. The curve is cut at its own knots and where it
// crosses the surface's interior knot lines u = U_k, v = V_k, so every piece lies
// on one polynomial patch of S; there S(c(t)) is a rational Bézier curve of degree
// at most d3d = p_c·(p_u + p_v). Pieces are in the curve's direction, ordered by t.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "geom/nurbs_curve.h"
#include "geom/nurbs_surface.h"

namespace trimkit::tess {

// Degree above which the lift is not attempted exactly: the equidistant Bernstein
// collocation matrix grows ill-conditioned ([Balazs] Sec. 4 suggests ~20); with
// bicubic surfaces and cubic trims d3d = 18. Larger pieces are fitted at this
// degree and flagged inexact.
constexpr int kMaxLiftDegree = 24;
// A lift is exact when it reproduces S(c(t)) at the samples and between them
// within this fraction of the piece's size (bounding-box diagonal of the samples).
constexpr double kLiftTolerance = 1e-9;
// A degree reduction is lossless when the reduced curve still reproduces the
// samples within this fraction of the size: far below kLiftTolerance, so a chain
// of reductions cannot use up the lift's budget, and far above the ~1e-14 noise of
// the SVD solve at d3d <= 18.
constexpr double kReductionTolerance = 1e-11;
// Breaks closer than this fraction of the curve's domain are merged (one crossing
// found twice, or a crossing at a curve knot); above kKnotTolerance (1e-10) so
// sub_curve never sees a piece shorter than its knot tolerance.
constexpr double kBreakMergeRelative = 1e-9;

// One lifted piece: c over [t0, t1] mapped through S, as a Bézier curve in s in
// [0, 1] with t = t0 + s (t1 - t0). P: homogeneous control points (w·x, w·y, w·z, w)
// (w = 1 for polynomial pieces).
struct LiftedPiece {
    double t0 = 0.0, t1 = 0.0;
    std::vector<Eigen::Vector4d> P;
    bool exact = true;  // reproduces S(c(t)) within kLiftTolerance (false: d3d too high)

    int degree() const { return static_cast<int>(P.size()) - 1; }
    double parameter(double s) const { return t0 + s * (t1 - t0); }
    Eigen::Vector3d evaluate(double s) const;  // the Euclidean point at s
};

// Parameters where c must be cut: the domain ends, c's interior knots and the
// crossings of c with the surface's interior knot lines, sorted, merged within
// kBreakMergeRelative. Crossings: roots of the Bernstein polynomial w(t)(u(t) - U_k)
// per Bézier segment of c by recursive subdivision (sign changes of the
// coefficients), refined to ~1e-14 of the segment.
std::vector<double> trim_curve_breaks(const geom::NurbsSurface& S, const geom::NurbsCurve2d& c);

// The lifted pieces over trim_curve_breaks(S, c). Each: d3d + 1 samples
// H(t_k) = W(t_k)^(p_u+p_v) · w_S(c(t_k)) · (S(c(t_k)), 1) at s_k = k / d3d (W, w_S the
// denominators of c and S; this scaling makes H a polynomial of degree d3d,
// re-derived), solved for Bernstein coefficients with Eigen's JacobiSVD, then
// degree-reduced while lossless ([Balazs] Sec. 4, after [Far96]: the reduction
// from both ends, joined at the middle, accepted when it reproduces the samples).
std::vector<LiftedPiece> lift_trim_curve(const geom::NurbsSurface& S, const geom::NurbsCurve2d& c);

}  // namespace trimkit::tess
