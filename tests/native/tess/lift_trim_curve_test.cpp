#include "tess/lift_trim_curve.h"

#include <gtest/gtest.h>

#include "tess/tess_test_cases.h"
#include "test_support.h"

namespace trimkit::tess {
namespace {

using test::TrimCase;

// The pieces cover the curve's domain in order and reproduce S(c(t)) within 1e-9
// of the surface's size, also between the fit samples.
void expect_exact_lift(const TrimCase& tc, int min_pieces) {
    const std::vector<LiftedPiece> pieces = lift_trim_curve(tc.surface, tc.curve);
    ASSERT_GE(static_cast<int>(pieces.size()), min_pieces) << tc.name;
    EXPECT_EQ(pieces.front().t0, tc.curve.domain().first);
    EXPECT_EQ(pieces.back().t1, tc.curve.domain().second);
    const double size = tc.surface.control_box().diagonal().norm();
    double worst = 0.0;
    for (size_t i = 0; i < pieces.size(); ++i) {
        if (i > 0) {
            EXPECT_EQ(pieces[i].t0, pieces[i - 1].t1);
        }
        EXPECT_TRUE(pieces[i].exact) << tc.name << " piece " << i;
        for (int k = 0; k <= 97; ++k) {
            const double s = k / 97.0;
            const Eigen::Vector2d uv = tc.curve.evaluate(pieces[i].parameter(s));
            const Eigen::Vector3d X = tc.surface.evaluate(uv.x(), uv.y());
            const Eigen::Vector3d B = pieces[i].evaluate(s);
            EXPECT_TRUE(test::is_finite(B));
            worst = std::max(worst, (B - X).norm());
        }
    }
    EXPECT_LE(worst, 1e-9 * size) << tc.name;
    std::printf("[lift] %s: %zu pieces, max |B(s) - S(c(t))| = %.3g (size %.3g)\n",
                tc.name.c_str(), pieces.size(), worst, size);
}

TEST(LiftTrimCurve, CircleOnSphereIsExact) { expect_exact_lift(test::sphere_circle(), 4); }
TEST(LiftTrimCurve, CircleOnSkewedBilinearIsExact) { expect_exact_lift(test::skewed_circle(), 4); }
TEST(LiftTrimCurve, LineOnCylinderIsExact) { expect_exact_lift(test::cylinder_line(), 2); }
TEST(LiftTrimCurve, CubicOnBicubicIsExact) {
    expect_exact_lift({"yang A", test::yang_surface(), test::yang_curve(false)}, 1);
}

TEST(LiftTrimCurve, SameAtLargeAndSmallScale) {
    for (double scale : {1e-6, 1e6}) {
        TrimCase tc = test::sphere_circle();
        tc.surface = tc.surface.transformed(Eigen::Affine3d(Eigen::Scaling(scale)) *
                                            Eigen::Translation3d(3, -2, 5));
        tc.name += " scale " + std::to_string(scale);
        expect_exact_lift(tc, 4);
    }
}

TEST(LiftTrimCurve, BreaksAtSurfaceKnotLines) {
    // Cylinder θ in [0, 3π/2]: knots at π/2 and π (ArcParameterMap, one per 90°).
    const TrimCase tc = test::cylinder_line();
    const std::vector<double> breaks = trim_curve_breaks(tc.surface, tc.curve);
    ASSERT_EQ(breaks.size(), 4u);
    for (size_t i = 1; i + 1 < breaks.size(); ++i) {
        const double u = tc.curve.evaluate(breaks[i]).x();
        EXPECT_NEAR(u, i * test::kPi / 2, 1e-12);
    }
}

TEST(LiftTrimCurve, ReducesDegreeLosslessly) {
    // Bilinear S, degree-1 trims: d3d = 2. An iso line v = 0.3 lifts to a straight
    // line (degree 1); a diagonal one stays quadratic.
    const geom::NurbsSurface S = test::skewed_bilinear();
    const auto iso = lift_trim_curve(S, geom::line_segment(Eigen::Vector2d(0.1, 0.3),
                                                           Eigen::Vector2d(0.9, 0.3)));
    ASSERT_EQ(iso.size(), 1u);
    EXPECT_EQ(iso[0].degree(), 1);
    const auto diag = lift_trim_curve(S, geom::line_segment(Eigen::Vector2d(0.1, 0.2),
                                                            Eigen::Vector2d(0.9, 0.7)));
    ASSERT_EQ(diag.size(), 1u);
    EXPECT_EQ(diag[0].degree(), 2);
    // A uv line on a plane patch: degree 1.
    const geom::NurbsSurface plane = geom::plane_patch(
        Eigen::Vector3d::Zero(), Eigen::Vector3d(2, 0, 1), Eigen::Vector3d(0, 1, 3), 0, 1, 0, 1);
    const auto flat = lift_trim_curve(plane, geom::line_segment(Eigen::Vector2d(0.1, 0.2),
                                                                Eigen::Vector2d(0.9, 0.7)));
    EXPECT_EQ(flat[0].degree(), 1);
}

}  // namespace
}  // namespace trimkit::tess
