// Domain sides a surface collapses to a point, and the polar map about them
// (tess/collapsed_side).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geom/analytic_surfaces.h"
#include "tess/collapsed_side.h"

namespace trimkit::tess {
namespace {

double ring_area(const std::vector<Eigen::Vector2d>& p) {
    double a = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const Eigen::Vector2d& x = p[i];
        const Eigen::Vector2d& y = p[(i + 1) % p.size()];
        a += x.x() * y.y() - y.x() * x.y();
    }
    return 0.5 * a;
}

// A cone from its apex (v = 0, radius 0) to radius 10 at v = 20 collapses only the
// side v = v0; a sphere collapses both latitude ends; a cylinder collapses none.
TEST(CollapsedSides, ApexAndPolesAreFoundAndNothingElse) {
    const Eigen::Vector3d O = Eigen::Vector3d::Zero(), Z = Eigen::Vector3d::UnitZ(), X = Eigen::Vector3d::UnitX();
    const CollapsedSides cone = collapsed_sides(geom::cone_patch(O, Z, X, 0.0, std::atan(0.5), 0, 2 * M_PI, 0, 20));
    EXPECT_EQ(cone, (CollapsedSides{false, false, true, false}));
    const CollapsedSides sphere = collapsed_sides(geom::sphere_patch(O, Z, X, 5, 0, 2 * M_PI, -M_PI / 2, M_PI / 2));
    EXPECT_EQ(sphere, (CollapsedSides{false, false, true, true}));
    const CollapsedSides cylinder = collapsed_sides(geom::cylinder_patch(O, Z, X, 5, 0, 2 * M_PI, 0, 10));
    EXPECT_EQ(cylinder, (CollapsedSides{false, false, false, false}));
}

// The map keeps orientation about every side, and puts every point of the side on
// the origin (the apex is one point, as in 3D).
TEST(PolarAboutSide, KeepsOrientationAndCollapsesTheSide) {
    const geom::NurbsSurface plane = geom::plane_patch(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(),
                                                       Eigen::Vector3d::UnitY(), 0, 2, 0, 3);
    const std::vector<Eigen::Vector2d> ccw = {{0.5, 0.5}, {1.5, 0.5}, {1.5, 2.5}, {0.5, 2.5}};
    for (int side = 0; side < 4; ++side)
        EXPECT_GT(ring_area(polar_about_side(plane, side, ccw)), 0.0) << "side " << side;
    const std::vector<Eigen::Vector2d> on_u0 = {{0, 0.3}, {0, 2.7}};
    for (const Eigen::Vector2d& p : polar_about_side(plane, 0, on_u0)) EXPECT_LT(p.norm(), 1e-15);
}

// A ring touching the collapsed side is reported with it; one that stays off it is not.
TEST(TouchedCollapsedSide, OnlyRingsOnTheSide) {
    const Eigen::Vector3d O = Eigen::Vector3d::Zero(), Z = Eigen::Vector3d::UnitZ(), X = Eigen::Vector3d::UnitX();
    const geom::NurbsSurface cone = geom::cone_patch(O, Z, X, 0.0, std::atan(0.5), 0, 2 * M_PI, 0, 20);
    const CollapsedSides sides = collapsed_sides(cone);
    const std::vector<Eigen::Vector2d> uv = {{1, 0}, {2, 0}, {2, 5}, {1, 5}, {1, 1}, {2, 1}};
    EXPECT_EQ(touched_collapsed_side(cone, sides, uv, {0, 1, 2, 3}), 2);
    EXPECT_EQ(touched_collapsed_side(cone, sides, uv, {4, 5, 2, 3}), -1);
}

}  // namespace
}  // namespace trimkit::tess
