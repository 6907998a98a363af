#include "geom/project_curve_adaptive.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geom/analytic_curves.h"
#include "geom/analytic_surfaces.h"

namespace trimkit::geom {
namespace {

constexpr double kPi = 3.14159265358979323846;

double positive_mod(double x, double p) {
    const double r = std::fmod(x, p);
    return r < 0 ? r + p : r;
}

// Largest distance from S(pcurve) (pcurve sampled finely, u taken modulo
// `period_u`) to the polyline through dense samples of c.
double deviation(const NurbsSurface& s, const NurbsCurve2d& pcurve, const NurbsCurve3d& c, double period_u) {
    std::vector<Eigen::Vector3d> poly;
    const auto [a, b] = c.domain();
    for (int k = 0; k <= 4000; ++k) poly.push_back(c.evaluate(a + (b - a) * k / 4000));
    double worst = 0;
    const auto [p0, p1] = pcurve.domain();
    for (int k = 0; k <= 1000; ++k) {
        Eigen::Vector2d uv = pcurve.evaluate(p0 + (p1 - p0) * k / 1000);
        if (period_u > 0) uv.x() = s.domain_u().first + positive_mod(uv.x() - s.domain_u().first, period_u);
        const Eigen::Vector3d x = s.evaluate(uv.x(), uv.y());
        double best = 1e300;
        for (std::size_t i = 0; i + 1 < poly.size(); ++i) {
            const Eigen::Vector3d d = poly[i + 1] - poly[i];
            const double t = std::clamp((x - poly[i]).dot(d) / d.squaredNorm(), 0.0, 1.0);
            best = std::min(best, (poly[i] + t * d - x).norm());
        }
        worst = std::max(worst, best);
    }
    return worst;
}

// A plane through the axis of a unit cylinder at slope 0.5 cuts it in an ellipse
// whose (u,v) image is the sine v = 0.5 cos u. Half of it, u from -π/2 to π/2,
// crosses the seam u = 0 of the cylinder on [0, 2π].
struct Cut {
    NurbsSurface cylinder = cylinder_patch(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(),
                                           Eigen::Vector3d::UnitX(), 1.0, 0, 2 * kPi, -1, 1);
    NurbsCurve3d ellipse = ellipse_arc(Eigen::Vector3d::Zero(), Eigen::Vector3d(1, 0, 0.5), Eigen::Vector3d::UnitY(),
                                       std::sqrt(1.25), 1.0, -kPi / 2, kPi / 2);
};

TEST(ProjectCurveAdaptive, FollowsACurveWhoseParameterImageIsCurved) {
    const Cut cut;
    const SurfaceProjector projector(cut.cylinder);
    // project_curve's 16 samples per span leave chords 0.5 Δu²/8 off the sine,
    // Δu = π/32: 6e-4.
    const NurbsCurve2d plain = project_curve(projector, cut.ellipse);
    constexpr double kTolerance = 1e-5;
    double max_distance = -1;
    const NurbsCurve2d refined =
        project_curve_adaptive(projector, cut.ellipse, kTolerance, 2 * kPi, 0.0, &max_distance);
    EXPECT_GT(deviation(cut.cylinder, plain, cut.ellipse, 2 * kPi), 1e-4);
    EXPECT_LT(deviation(cut.cylinder, refined, cut.ellipse, 2 * kPi), 2 * kTolerance);
    EXPECT_LT(max_distance, 1e-9);  // every point is on the curve (the curve lies on the cylinder)
    EXPECT_GT(refined.points().size(), plain.points().size());
    EXPECT_EQ(refined.domain(), cut.ellipse.domain());
}

TEST(ProjectCurveAdaptive, ACurveAcrossTheSeamRunsOnPastTheDomain) {
    const Cut cut;
    const SurfaceProjector projector(cut.cylinder);
    const NurbsCurve2d c = project_curve_adaptive(projector, cut.ellipse, 1e-5, 2 * kPi, 0.0);
    // Continuous: no step between points comes near the period.
    double step = 0;
    for (std::size_t k = 1; k < c.points().size(); ++k)
        step = std::max(step, std::abs(c.points()[k].x() - c.points()[k - 1].x()));
    EXPECT_LT(step, 0.2);
    // It spans half a turn, π, past one end of [0, 2π].
    const double u0 = c.points().front().x(), u1 = c.points().back().x();
    EXPECT_NEAR(u1 - u0, kPi, 1e-9);
    EXPECT_TRUE(u0 < 0 || u1 > 2 * kPi) << u0 << " .. " << u1;
    EXPECT_NEAR(c.points()[c.points().size() / 2].y(), 0.5, 1e-3);  // v = 0.5 cos 0 at the seam
    // Without the period the projection jumps across the domain at the seam.
    const NurbsCurve2d jumping = project_curve_adaptive(projector, cut.ellipse, 1e-5);
    double jump = 0;
    for (std::size_t k = 1; k < jumping.points().size(); ++k)
        jump = std::max(jump, std::abs(jumping.points()[k].x() - jumping.points()[k - 1].x()));
    EXPECT_GT(jump, kPi);
}

TEST(ProjectCurveAdaptive, ExactPlaneProjectionIsKept) {
    const NurbsSurface plane = plane_patch(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
                                           -2, 2, -2, 2);
    const NurbsCurve3d circle = circular_arc(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(),
                                             Eigen::Vector3d::UnitY(), 1.0, 0, 2 * kPi);
    const SurfaceProjector projector(plane);
    const NurbsCurve2d c = project_curve_adaptive(projector, circle, 1e-9);
    EXPECT_EQ(c.degree(), 2);  // the circle mapped control point by control point
    EXPECT_LT(deviation(plane, c, circle, 0.0), 1e-12);
}

}  // namespace
}  // namespace trimkit::geom
