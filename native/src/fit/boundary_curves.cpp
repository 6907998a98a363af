#include "fit/boundary_curves.h"

#include "fit/fit_curve.h"

namespace trimkit::fit {
namespace {

// Smoothing of the boundary curves: enough to bridge a side that the lines meet
// only in part, small against the points' mean squared error.
constexpr double kCurveSmoothing = 1e-5;

std::optional<geom::NurbsCurve3d> fit_side(const std::vector<std::pair<double, Eigen::Vector3d>>& points, int degree,
                                           int count, const std::optional<Eigen::Vector3d>& start,
                                           const std::optional<Eigen::Vector3d>& end) {
    if (static_cast<int>(points.size()) < kMinSidePoints) return std::nullopt;
    CurveFitProblem problem;
    problem.degree = degree;
    problem.count = count;
    problem.smoothing = kCurveSmoothing;
    for (const auto& [t, x] : points) {
        problem.params.push_back(t);
        problem.points.push_back(x);
    }
    problem.start = start;
    problem.end = end;
    return fit_curve(problem);
}

}  // namespace

BoundaryCurves boundary_curves(const OutsideSamples& samples, const FitRule& rule) {
    const auto degree = [&](int side) { return side < 2 ? rule.degree_v : rule.degree_u; };
    const auto count = [&](int side) { return side < 2 ? rule.count_v : rule.count_u; };
    BoundaryCurves first;
    for (int s = 0; s < 4; ++s) first.sides[s] = fit_side(samples.sides[s], degree(s), count(s), {}, {});
    // Corner (i, j) at u = i, v = j: the end j of side i and the end i of side 2 + j.
    std::optional<Eigen::Vector3d> corner[2][2];
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) {
            Eigen::Vector3d sum = Eigen::Vector3d::Zero();
            int n = 0;
            if (first.sides[i]) sum += j ? first.sides[i]->points().back() : first.sides[i]->points().front(), ++n;
            if (first.sides[2 + j]) sum += i ? first.sides[2 + j]->points().back() : first.sides[2 + j]->points().front(), ++n;
            if (n) corner[i][j] = sum / n;
        }
    BoundaryCurves curves;
    for (int s = 0; s < 4; ++s) {
        const bool along_v = s < 2;
        const auto& start = along_v ? corner[s][0] : corner[0][s - 2];
        const auto& end = along_v ? corner[s][1] : corner[1][s - 2];
        curves.sides[s] = fit_side(samples.sides[s], degree(s), count(s), start, end);
    }
    return curves;
}

std::vector<std::optional<Eigen::Vector3d>> boundary_rows(const BoundaryCurves& curves, int nu, int nv) {
    std::vector<std::optional<Eigen::Vector3d>> fixed(nu * nv);
    for (int s = 0; s < 4; ++s) {
        if (!curves.sides[s]) continue;
        const auto& P = curves.sides[s]->points();
        if (s < 2)
            for (int j = 0; j < nv; ++j) fixed[(s == 0 ? 0 : nu - 1) * nv + j] = P[j];
        else
            for (int i = 0; i < nu; ++i) fixed[i * nv + (s == 2 ? 0 : nv - 1)] = P[i];
    }
    return fixed;
}

}  // namespace trimkit::fit
