#include "fit/fit_curve.h"

#include <cmath>
#include <string>

#include "fit/least_squares_system.h"
#include "fit/smoothing_rows.h"
#include "geom/bspline_basis.h"
#include "geom/error.h"
#include "geom/knot_vector.h"

namespace trimkit::fit {
namespace {

void validate(const CurveFitProblem& f) {
    if (f.degree < 1 || f.degree > geom::kMaxDegree)
        throw geom::InvalidInput("fit_curve: degree " + std::to_string(f.degree) + "; expected 1 .. " +
                                 std::to_string(geom::kMaxDegree));
    if (f.count < f.degree + 1 || f.count > kMaxFitControlPoints)
        throw geom::InvalidInput("fit_curve: " + std::to_string(f.count) + " control points; expected " +
                                 std::to_string(f.degree + 1) + " .. " + std::to_string(kMaxFitControlPoints));
    if (f.params.size() != f.points.size())
        throw geom::InvalidInput("fit_curve: " + std::to_string(f.params.size()) + " parameters for " +
                                 std::to_string(f.points.size()) + " points");
    for (std::size_t k = 0; k < f.params.size(); ++k)
        if (!(f.params[k] >= 0 && f.params[k] <= 1) || !f.points[k].allFinite())
            throw geom::InvalidInput("fit_curve: sample " + std::to_string(k) + " at t = " +
                                     geom::format_value(f.params[k]) + "; expected finite, t in [0, 1]");
    if (!(f.smoothing >= 0) || !std::isfinite(f.smoothing))
        throw geom::InvalidInput("fit_curve: smoothing " + geom::format_value(f.smoothing) + "; expected >= 0");
}

}  // namespace

geom::NurbsCurve3d fit_curve(const CurveFitProblem& f) {
    validate(f);
    const std::vector<double> U = geom::uniform_clamped_knots(f.count, f.degree);
    LeastSquaresSystem system(3 * f.count);
    const double w = 1.0 / std::sqrt(static_cast<double>(std::max<std::size_t>(1, f.points.size())));
    std::vector<double> N(f.degree + 1);
    for (std::size_t k = 0; k < f.points.size(); ++k) {
        const int span = geom::knot_span(U, f.degree, f.params[k]);
        geom::basis_functions(U, f.degree, span, f.params[k], N.data());
        for (int c = 0; c < 3; ++c) {
            std::vector<std::pair<int, double>> row;
            for (int j = 0; j <= f.degree; ++j) row.emplace_back(3 * (span - f.degree + j) + c, N[j]);
            system.add_row(row, f.points[k][c], w);
        }
    }
    add_smoothing_rows(system, f.count, 1, std::sqrt(f.smoothing));
    for (int c = 0; c < 3; ++c) {
        if (f.start) system.fix(c, (*f.start)[c]);
        if (f.end) system.fix(3 * (f.count - 1) + c, (*f.end)[c]);
    }
    const Eigen::VectorXd x = system.solve("fit_curve");
    std::vector<Eigen::Vector3d> P(f.count);
    for (int i = 0; i < f.count; ++i) P[i] = x.segment<3>(3 * i);
    return geom::NurbsCurve3d(f.degree, U, std::move(P));
}

}  // namespace trimkit::fit
