// Approximating one trim curve (a coedge's 2D curve c in the face's (u,v) domain)
// by a polyline whose 3D image is within a tolerance of the exact curve S(c(t)).
// Points run in c's direction from its domain start to end, both included; each
// carries t, uv = c(t) and xyz = S(uv). Tolerances are in model units.
#pragma once

#include <cstddef>

#include "geom/nurbs_curve.h"
#include "geom/nurbs_surface.h"
#include "mesh/deadline.h"
#include "tess/trim_polyline.h"

namespace trimkit::tess {

// Share of the tolerance for the approximation; the rest (1 - γ) goes to the
// simplification. [Balazs] Sec. 5.1 ("a good tradeoff ... γ = 3/4").
constexpr double kTrimGamma = 0.75;
// kBezier3d: midpoint subdivision stops at pieces 2^-kMaxSubdivisionDepth of a
// lifted piece (only reached if the bound cannot converge, e.g. a rational piece
// whose fitted weights are not positive).
constexpr int kMaxSubdivisionDepth = 40;
// kYang, kParam: cap on the segments per piece, so absurd bounds (huge weight
// ratios) cannot exhaust memory; 2^20 segments of one piece is far beyond need.
constexpr long kMaxStepsPerPiece = 1L << 20;
// Cap on the points of one trim polyline (all pieces): a curve whose (u,v) extent is
// absurd for its surface (a fuzzed plane 7e11 wide) would otherwise take hundreds of
// MB before the face's time limit; the face fails instead, with the figures.
constexpr std::size_t kMaxTrimPoints = std::size_t(1) << 19;

// The polyline for c on S, to `tolerance` (> 0) by `method`:
//  kBezier3d [Balazs] Sec. 4, 5.1: on each lifted piece (lift_trim_curve) midpoint
//    subdivision (de Casteljau) until e_line + e_uv <= γ·tol, where e_line is the
//    largest distance of the (projected) control points from the chord ([Balazs]
//    Sec. 5.1 without the factor 1 - 2^(2-n), which does not hold for rational or
//    low-degree pieces: departure) and e_uv = sqrt((M^u)² + (M^v)²)·max|c(s) - l(s)|
//    bounds the image under S of the uv chord l ([Yang] eq. 7 with Cauchy-Schwarz
//    in place of M^u + M^v: departure, tighter; |c - l| from the control points of
//    the numerator of c - l, re-derived), so points the surface grid adds on a
//    segment stay within tolerance too (departure from [Balazs], which bounds the
//    3D chord only). On an affine S (NurbsSurface::is_affine: plane patches) S maps
//    the uv chord onto the 3D chord, so e_uv = 0 there. Then simplify_trim_polyline
//    with (1 - γ)·tol, or against the pieces' hulls (`simplification` below).
//    Inexact lifts (d3d > kMaxLiftDegree) use the kYang steps with γ·tol.
//  kYang [Yang] eq. 9-11: per piece of trim_curve_breaks, dt = sqrt(tol / (M1 + M2)),
//    M1 = (M^u + M^v) M^tt / 8, M2 = (M^uu (M^t_u)² + 2 M^uv M^t_u M^t_v + M^vv (M^t_v)²) / 8,
//    the M's from derivative_bounds over the piece's uv box; uniform steps.
//  kParam [Yang] Sec. 2.2: per Bézier segment of c, n = ceil(Δt sqrt(sup|c''| / (8 tol)))
//    uniform steps. Bounds the error in (u,v) only: NO 3D guarantee (baseline).
// Simplification (kBezier3d) is per coedge: its end points stay, so shared edges
// and loop joints keep their vertices.
// Throws InvalidInput if tolerance is not finite and > 0.
// `deadline`: checked per lifted piece and per point evaluated (up to kMaxStepsPerPiece a
// piece); throws mesh::DeadlineExceeded once it has passed.
//
// kBezier3d's simplification (`simplification`):
//  kHulls: simplify_trim_polyline against the subdivided pieces' control hulls with the
//    whole tolerance (chords across knot lines and pieces; fewest points);
//  kPoints: [Balazs] Sec. 5.1 as written, the points simplified with (1 - γ)·tol. Two
//    faces that approximate one curve each on their own (an edge the file does not
//    share, or whose faces lie too far apart to share one polyline) place their points
//    alike along it, so the join can weld them; long chords of each would not meet.
enum class TrimSimplification { kHulls, kPoints };
TrimPolyline approximate_trim_curve(const geom::NurbsSurface& S, const geom::NurbsCurve2d& c,
                                    double tolerance, TrimMethod method, mesh::Deadline* deadline = nullptr,
                                    TrimSimplification simplification = TrimSimplification::kHulls);

}  // namespace trimkit::tess
