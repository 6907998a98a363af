// Least-squares B-spline curve fitting: a non-rational, clamped, uniform-knot curve
// on [0, 1] approximating points Q_k at given parameters t_k, optionally through
// fixed end points, with the smoothing term of smoothing_rows.h. [PT] Sec. 9.4.1
// (the least-squares system N^T N P = N^T R), with the end points fixed as there.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "geom/nurbs_curve.h"

namespace trimkit::fit {

// Most control points per direction a fitter accepts (a .tkz stores the count;
// reading a larger one is refused before anything is allocated).
constexpr int kMaxFitControlPoints = 64;

struct CurveFitProblem {
    int degree = 3;
    int count = 4;                        // control points, degree + 1 .. kMaxFitControlPoints
    std::vector<double> params;           // t_k in [0, 1]
    std::vector<Eigen::Vector3d> points;  // Q_k, one per parameter
    std::optional<Eigen::Vector3d> start, end;  // C(0), C(1) when given
    double smoothing = 1e-6;              // weight of the energy against the mean squared error
};

// Throws geom::InvalidInput for a bad degree or count, mismatched or non-finite
// samples or parameters outside [0, 1]; geom::NumericalFailure when the system is
// singular (too few samples and no smoothing).
geom::NurbsCurve3d fit_curve(const CurveFitProblem& problem);

}  // namespace trimkit::fit
