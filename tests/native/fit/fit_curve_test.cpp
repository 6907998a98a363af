// fit/fit_curve: recovery of known curves, the smoothing term's null space
// (affine control polygons), fixed ends, and the Fig. 17 failure without smoothing.
#include "fit/fit_curve.h"

#include <gtest/gtest.h>

#include "geom/error.h"
#include "geom/knot_vector.h"

namespace trimkit::fit {
namespace {

geom::NurbsCurve3d known_cubic() {
    // 6 points, degree 3, uniform clamped: the fitter's own knot vector.
    std::vector<Eigen::Vector3d> P = {{0, 0, 0}, {1, 2, 0}, {2, -1, 1}, {3, 3, 2}, {4, 0, -1}, {5, 1, 0}};
    return geom::NurbsCurve3d(3, geom::uniform_clamped_knots(6, 3), P);
}

TEST(FitCurve, RecoversTheControlPointsOfACurveInItsSpace) {
    const geom::NurbsCurve3d c = known_cubic();
    CurveFitProblem f;
    f.count = 6;
    f.smoothing = 0;
    for (int k = 0; k <= 40; ++k) {
        f.params.push_back(k / 40.0);
        f.points.push_back(c.evaluate(k / 40.0));
    }
    const geom::NurbsCurve3d fit = fit_curve(f);
    ASSERT_EQ(fit.points().size(), 6u);
    for (int i = 0; i < 6; ++i) EXPECT_LT((fit.points()[i] - c.points()[i]).norm(), 1e-10) << i;
}

TEST(FitCurve, SmoothingLeavesAnEvenlyParameterisedLineExact) {
    // A Bézier cubic's Greville abscissae 0, 1/3, 2/3, 1 are evenly spaced, so the
    // line A + t (B - A) has an affine control polygon: zero energy, zero error.
    const Eigen::Vector3d A(1, 2, 3), B(-4, 0, 7);
    CurveFitProblem f;
    f.count = 4;
    f.smoothing = 0.1;
    for (double t : {0.0, 0.3, 0.5, 1.0}) {
        f.params.push_back(t);
        f.points.push_back(A + t * (B - A));
    }
    const geom::NurbsCurve3d fit = fit_curve(f);
    for (int i = 0; i < 4; ++i) EXPECT_LT((fit.points()[i] - (A + (i / 3.0) * (B - A))).norm(), 1e-12) << i;
    EXPECT_LT((fit.evaluate(0.77) - (A + 0.77 * (B - A))).norm(), 1e-12);
}

TEST(FitCurve, FixedEndsAreInterpolated) {
    CurveFitProblem f;
    f.count = 8;
    for (int k = 0; k <= 30; ++k) {
        const double t = k / 30.0;
        f.params.push_back(t);
        f.points.push_back({t, std::sin(3 * t), 0});
    }
    f.start = Eigen::Vector3d(0, 0.1, 0);
    f.end = Eigen::Vector3d(1, 0.0, 0.5);
    const geom::NurbsCurve3d fit = fit_curve(f);
    EXPECT_EQ((fit.evaluate(0) - *f.start).norm(), 0.0);
    EXPECT_LT((fit.evaluate(1) - *f.end).norm(), 1e-15);
}

TEST(FitCurve, FewSamplesNeedTheSmoothingTerm) {
    // 3 samples cannot fix 8 control points ([Muraki] Fig. 17); the energy can.
    CurveFitProblem f;
    f.count = 8;
    f.smoothing = 0;
    f.params = {0.0, 0.5, 1.0};
    f.points = {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}};
    EXPECT_THROW(fit_curve(f), geom::NumericalFailure);
    f.smoothing = 1e-4;
    const geom::NurbsCurve3d fit = fit_curve(f);
    for (int k = 0; k < 3; ++k) EXPECT_LT((fit.evaluate(f.params[k]) - f.points[k]).norm(), 0.05) << k;
}

TEST(FitCurve, RejectsBadInput) {
    CurveFitProblem f;
    f.count = 3;  // below degree + 1
    EXPECT_THROW(fit_curve(f), geom::InvalidInput);
    f.count = 4;
    f.params = {0.5, 1.5};
    f.points = {{0, 0, 0}, {1, 0, 0}};
    EXPECT_THROW(fit_curve(f), geom::InvalidInput);
}

}  // namespace
}  // namespace trimkit::fit
