// fit/fit_surface: recovery of a known bicubic, fixed boundary rows, tangent-plane
// (G1) rows and the smoothing term with few samples.
#include "fit/fit_surface.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geom/error.h"
#include "geom/knot_vector.h"

namespace trimkit::fit {
namespace {

// A 5 x 6 bicubic on the fitter's knots, z from a fixed table.
geom::NurbsSurface known_bicubic() {
    std::vector<Eigen::Vector3d> P;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 6; ++j) P.push_back({i * 1.0, j * 0.8, std::sin(1.3 * i) * std::cos(0.7 * j)});
    return geom::NurbsSurface(3, 3, geom::uniform_clamped_knots(5, 3), geom::uniform_clamped_knots(6, 3), 5, 6, P);
}

SurfaceFitProblem grid_problem(const geom::NurbsSurface& s, int n) {
    SurfaceFitProblem f;
    f.count_u = s.count_u();
    f.count_v = s.count_v();
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
            const Eigen::Vector2d uv(i / double(n), j / double(n));
            f.points.push_back({uv, s.evaluate(uv.x(), uv.y()), 1.0});
        }
    return f;
}

TEST(FitSurface, RecoversAKnownBicubic) {
    const geom::NurbsSurface s = known_bicubic();
    SurfaceFitProblem f = grid_problem(s, 15);
    f.smoothing = 0;
    const geom::NurbsSurface fit = fit_surface(f);
    for (std::size_t k = 0; k < s.points().size(); ++k) EXPECT_LT((fit.points()[k] - s.points()[k]).norm(), 1e-9) << k;
}

TEST(FitSurface, FixedBoundaryRowsAreKeptAndTheInteriorRecovered) {
    const geom::NurbsSurface s = known_bicubic();
    SurfaceFitProblem f = grid_problem(s, 12);
    f.smoothing = 0;
    f.fixed.resize(30);
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 6; ++j)
            if (i == 0 || i == 4 || j == 0 || j == 5) f.fixed[i * 6 + j] = s.point(i, j);
    const geom::NurbsSurface fit = fit_surface(f);
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 6; ++j) {
            if (f.fixed[i * 6 + j]) {
                EXPECT_EQ(fit.point(i, j), s.point(i, j));
            }
            EXPECT_LT((fit.point(i, j) - s.point(i, j)).norm(), 1e-9);
        }
}

TEST(FitSurface, TangentPlaneRowsSetTheNormal) {
    // Points of the paraboloid z = (x² + y²)/2 over [0,1]², except near (0.5, 0.5)
    // where the fit is told the tangent plane has normal n (tilted 10° about y).
    SurfaceFitProblem f;
    f.count_u = f.count_v = 6;
    for (int i = 0; i <= 10; ++i)
        for (int j = 0; j <= 10; ++j) {
            const double x = i / 10.0, y = j / 10.0;
            f.points.push_back({{x, y}, {x, y, 0.5 * (x * x + y * y)}, 1.0});
        }
    const double a = 10.0 * M_PI / 180;
    const Eigen::Vector3d n(-std::sin(a), 0, std::cos(a));
    f.tangent_planes.push_back({{0.0, 0.5}, n, 1.0});
    f.tangent_weight = 1e8;
    const geom::NurbsSurface fit = fit_surface(f);
    const double angle = std::acos(std::min(1.0, fit.normal(0.0, 0.5).dot(n)));
    EXPECT_LT(angle * 180 / M_PI, 0.1);
    // Without the row the normal there is the paraboloid's, (0, -0.5, 1) normalised at (0, 0.5), 28° from n.
    f.tangent_planes.clear();
    const Eigen::Vector3d free_normal = fit_surface(f).normal(0.0, 0.5);
    EXPECT_GT(std::acos(std::min(1.0, free_normal.dot(n))) * 180 / M_PI, 5.0);
}

TEST(FitSurface, ThreeSamplesAndSmoothingGiveTheirPlane) {
    // The energy vanishes on affine nets, so samples of the plane z = 2x - y + 1,
    // with (u, v) = (x, y), are reproduced everywhere by a 4 x 4 net that 3 points alone leave free.
    SurfaceFitProblem f;
    f.count_u = f.count_v = 4;  // Bézier: evenly spaced Greville abscissae
    f.smoothing = 1e-3;
    for (const Eigen::Vector2d& uv : {Eigen::Vector2d(0.1, 0.2), Eigen::Vector2d(0.9, 0.3), Eigen::Vector2d(0.4, 0.8)})
        f.points.push_back({uv, {uv.x(), uv.y(), 2 * uv.x() - uv.y() + 1}, 1.0});
    const geom::NurbsSurface fit = fit_surface(f);
    EXPECT_LT((fit.evaluate(0.65, 0.05) - Eigen::Vector3d(0.65, 0.05, 2 * 0.65 - 0.05 + 1)).norm(), 1e-9);
    f.smoothing = 0;
    EXPECT_THROW(fit_surface(f), geom::NumericalFailure);
}

TEST(FitSurface, RejectsSamplesOutsideTheDomain) {
    SurfaceFitProblem f;
    f.points.push_back({{1.5, 0.0}, {0, 0, 0}, 1.0});
    EXPECT_THROW(fit_surface(f), geom::InvalidInput);
}

}  // namespace
}  // namespace trimkit::fit
