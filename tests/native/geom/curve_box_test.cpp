// geom::curve_box: tight boxes of 2D NURBS curves, against extremes derived by hand.
#include "geom/curve_box.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geom/error.h"

namespace trimkit::geom {
namespace {

// The quarter circle of radius 1 from (1, 0) to (0, 1), rational quadratic, turned by
// `angle`: its box's extremes are where the turned arc crosses an axis direction.
NurbsCurve2d quarter_circle(double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    auto turned = [&](double x, double y) { return Eigen::Vector2d(c * x - s * y, s * x + c * y); };
    return NurbsCurve2d(2, {0, 0, 0, 1, 1, 1}, {turned(1, 0), turned(1, 1), turned(0, 1)},
                        {1.0, std::sqrt(0.5), 1.0});
}

TEST(CurveBox, TurnedQuarterCircleIsBoxedAtItsTrueExtremes) {
    // Turned by 30 degrees the arc runs from angle 30 to 120 degrees: x from cos 120 to
    // cos 30, y from sin 30 up to 1 (at 90 degrees, inside the arc). The control box
    // reaches y = sqrt(2) sin 75 = 1.366.
    const double a = M_PI / 6, tol = 1e-12;
    const Eigen::AlignedBox2d box = curve_box(quarter_circle(a), tol);
    EXPECT_NEAR(box.min().x(), std::cos(a + M_PI / 2), 2 * tol);
    EXPECT_NEAR(box.max().x(), std::cos(a), 2 * tol);
    EXPECT_NEAR(box.min().y(), std::sin(a), 2 * tol);
    EXPECT_NEAR(box.max().y(), 1.0, 2 * tol);
    EXPECT_GT(quarter_circle(a).control_box().max().y(), 1.3);
}

TEST(CurveBox, CubicBulgeIsBoxedAtItsDerivativesRoot) {
    // y(t) = 3 t (1 - t)^2 h + 3 t^2 (1 - t) h for controls (0, 0), (1, h), (2, h), (3, 0):
    // y = 3 h t (1 - t), largest at t = 1/2: 3h/4, not the control polygon's h.
    // Two spans: the knot at 1/2 splits it into two Bézier segments.
    const double h = 2.0;
    const NurbsCurve2d c(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0}, {1, h}, {2, h}, {3, 0}});
    const NurbsCurve2d split = c.insert_knot(0.5, 1);
    for (const NurbsCurve2d& curve : {c, split}) {
        const Eigen::AlignedBox2d box = curve_box(curve, 1e-12);
        EXPECT_NEAR(box.max().y(), 0.75 * h, 1e-11);
        EXPECT_NEAR(box.min().y(), 0.0, 1e-15);
        EXPECT_NEAR(box.min().x(), 0.0, 1e-15);
        EXPECT_NEAR(box.max().x(), 3.0, 1e-15);
    }
}

TEST(CurveBox, CoarseToleranceStaysWithinIt) {
    const double tol = 1e-3;
    const Eigen::AlignedBox2d box = curve_box(quarter_circle(M_PI / 6), tol);
    EXPECT_LE(box.max().y(), 1.0 + tol);
    EXPECT_GE(box.max().y(), 1.0 - tol);
}

}  // namespace
}  // namespace trimkit::geom
