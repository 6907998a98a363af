// Curve interpolation: B-spline curves through given points, and the refit of a
// parameter-space curve through a non-linear map of its plane (the IGES reader's
// move of trim curves from an analytic surface's native (θ, ...) space to the
// NURBS (t, ...) space). Interpolants are non-rational and clamped; parameter
// values are strictly increasing and become the curve's parameters at the points.
#pragma once

#include <functional>
#include <vector>

#include <Eigen/Core>

#include "geom/nurbs_curve.h"

namespace trimkit::geom {

// ---- Global interpolation ---------------------------------------------------------

// Chord-length parameters of Q on [0, 1] ([PT] Eq. 9.5). Throws InvalidInput
// if two consecutive points coincide (the parameters would repeat).
template <int Dim>
std::vector<double> chord_length_parameters(const std::vector<Eigen::Matrix<double, Dim, 1>>& Q);

// The degree-p curve through Q_0 .. Q_n with C(params[k]) = Q_k, p = min(degree,
// n); empty params: chord length on [0, 1]. Knots by averaging ([PT] Eq. 9.8);
// the banded system N P = Q is solved with a sparse LU. [PT] Algorithm A9.1.
// Throws InvalidInput for fewer than 2 points, non-finite values, a params size
// mismatch or non-increasing params; NumericalFailure if the system is singular.
template <int Dim>
NurbsCurve<Dim> interpolate_curve(const std::vector<Eigen::Matrix<double, Dim, 1>>& Q,
                                  int degree = 3, std::vector<double> params = {});

extern template std::vector<double> chord_length_parameters(const std::vector<Eigen::Vector2d>&);
extern template std::vector<double> chord_length_parameters(const std::vector<Eigen::Vector3d>&);
extern template NurbsCurve<2> interpolate_curve(const std::vector<Eigen::Vector2d>&, int,
                                                std::vector<double>);
extern template NurbsCurve<3> interpolate_curve(const std::vector<Eigen::Vector3d>&, int,
                                                std::vector<double>);

// ---- Refit through a map -------------------------------------------------------------

// Most samples refit_mapped_curve may use before giving up.
constexpr int kMaxRefitSamples = 4096;

// Coordinate lines of the source plane across which a map is only C1 (e.g. the
// interior knot angles of an ArcParameterMap, ArcParameterMap::angles() without
// its ends). A cubic fit across them converges slowly (only the refinement at
// the crossing saves it), so the refit puts a C0 knot wherever the curve crosses one.
struct MapBreaks {
    std::vector<double> u;  // lines x = u[i]
    std::vector<double> v;  // lines y = v[i]
};

// A cubic B-spline approximating map(c(t)) on c's domain, parameterised by c's
// own parameter t, with |fit(t) - map(c(t))| < tolerance at the midpoints
// between samples. Sampling starts at 4 intervals per knot span; intervals whose
// midpoint deviates get their midpoint added until none does. The fit is split
// (C0) at c's knots of continuity below C2 and at crossings of `breaks`.
// Throws InvalidInput if tolerance <= 0, NumericalFailure if map returns a
// non-finite point or kMaxRefitSamples samples do not reach the tolerance.
NurbsCurve2d refit_mapped_curve(const NurbsCurve2d& c,
                                std::function<Eigen::Vector2d(Eigen::Vector2d)> map,
                                double tolerance, const MapBreaks& breaks = {});

}  // namespace trimkit::geom
