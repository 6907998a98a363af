// SurfaceProjector and project_curve at a sphere's pole, where the longitude is free:
// a curve that starts at (or a hair off) the pole keeps the longitude of the rest of
// the curve there, so a seam edge running into the pole stays on its iso-line (IGES
// B-rep spheres whose seam edges end at the poles: the loop closer cannot tell the
// seam's sides apart otherwise).
#include "geom/surface_projector.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geom/analytic_curves.h"
#include "geom/analytic_surfaces.h"

namespace trimkit::geom {
namespace {

constexpr double kPi = 3.14159265358979323846;

NurbsSurface unit_sphere(double radius) {
    return sphere_patch(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(), radius, 0,
                        2 * kPi, -kPi / 2, kPi / 2);
}

Eigen::Vector3d on_sphere(double radius, double longitude, double latitude) {
    return radius * Eigen::Vector3d(std::cos(latitude) * std::cos(longitude),
                                    std::cos(latitude) * std::sin(longitude), std::sin(latitude));
}

// Every point of the projected curve at the u of its middle point.
void expect_one_longitude(const NurbsCurve2d& c) {
    const auto [a, b] = c.domain();
    const double u = c.evaluate(0.5 * (a + b)).x();
    for (const Eigen::Vector2d& p : c.points()) EXPECT_NEAR(p.x(), u, 1e-9) << "point at v = " << p.y();
}

TEST(SurfaceProjector, MeridianFromThePoleKeepsItsLongitudeAtThePole) {
    const double R = 25, longitude = 2.0;
    const NurbsSurface sphere = unit_sphere(R);
    const SurfaceProjector projector(sphere);
    const Eigen::Vector3d towards(std::cos(longitude), std::sin(longitude), 0);
    // From the north pole (angle 0 from the axis) down to the equator.
    const NurbsCurve3d meridian = circular_arc(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), towards, R, 0, kPi / 2);
    const NurbsCurve2d uv = project_curve(projector, meridian);
    expect_one_longitude(uv);
    EXPECT_NEAR(uv.points().front().y(), kPi / 2, 1e-9);
    // The same curve the other way: it ends at the pole.
    expect_one_longitude(project_curve(projector, meridian.reversed()));
}

TEST(SurfaceProjector, CurveStartingAHairOffThePoleTakesTheLongitudeOfItsOtherPoints) {
    const double R = 25;
    const NurbsSurface sphere = unit_sphere(R);
    const SurfaceProjector projector(sphere);
    // A file's vertex 1e-9 R off the pole towards longitude 0.5, then a line to latitude
    // 1.2 at longitude 2: at the first point any longitude is within 1e-9 R of it.
    const Eigen::Vector3d start = on_sphere(R, 0.5, kPi / 2 - 1e-9);
    const NurbsCurve3d line = line_segment(start, on_sphere(R, 2.0, 1.2), 0, 1);
    const NurbsCurve2d uv = project_curve(projector, line);
    ASSERT_GE(uv.points().size(), 3u);
    EXPECT_NEAR(uv.points()[0].x(), uv.points()[1].x(), 1e-9);
    EXPECT_NEAR(uv.points()[0].y(), kPi / 2, 1e-6);
}

// A latitude circle 0.1355 rad below the pole (OCCT's Pump_TopCover.brep through
// its IGES writer: a 15 mm hole around a sphere's pole, R = 110.7): the pole is
// the nearest start of the coarse grid, and Newton from a pole, where u is free,
// stayed there: every point went to the pole and the loop was bridged with a line.
TEST(SurfaceProjector, PointsNearAPoleAreNotDrawnIntoIt) {
    const double R = 110.7, latitude = kPi / 2 - 0.1355;
    const NurbsSurface sphere = unit_sphere(R);
    const SurfaceProjector projector(sphere);
    // (The rational sphere's parameters are not its angles: compare points.)
    for (double longitude : {0.3, 1.0, 2.5, 4.0, 5.9}) {
        const Eigen::Vector3d x = on_sphere(R, longitude, latitude);
        const Eigen::Vector2d uv = projector.invert(x);
        EXPECT_NEAR((sphere.evaluate(uv.x(), uv.y()) - x).norm(), 0.0, 1e-9 * R) << "longitude " << longitude;
    }
    // A quarter of the circle: its image stays on the latitude circle's plane.
    const Eigen::Vector3d centre(0, 0, R * std::sin(latitude));
    const NurbsCurve3d arc = circular_arc(centre, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
                                          R * std::cos(latitude), 0.3, 0.3 + kPi / 2);
    const NurbsCurve2d image = project_curve(projector, arc);
    for (const Eigen::Vector2d& p : image.points())
        EXPECT_NEAR(sphere.evaluate(p.x(), p.y()).z(), centre.z(), 1e-9 * R);
}

// A spindle torus (major radius 4.85 under the minor 54.5, OCCT's Bottom.brep):
// by its axis, samples of every longitude lie close together, and Newton from
// the nearest one stopped 2.35 away in another basin; the latitude circle the
// face is trimmed by was projected onto the wrong circle and the loop bridged.
TEST(SurfaceProjector, SpindleTorusByItsAxisFindsTheFootInTheRightBasin) {
    const double R = 4.85, r = 54.5, phi = std::acos((13.66 - R) / r);
    const NurbsSurface torus = torus_patch(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(),
                                           R, r, 0, 2 * kPi, -kPi, kPi);
    const SurfaceProjector projector(torus);
    for (double theta = 0.05; theta < 2 * kPi; theta += 0.25) {
        const Eigen::Vector3d x = (R + r * std::cos(phi)) * Eigen::Vector3d(std::cos(theta), std::sin(theta), 0) +
                                  r * std::sin(phi) * Eigen::Vector3d::UnitZ();
        const Eigen::Vector2d uv = projector.invert(x);
        EXPECT_NEAR((torus.evaluate(uv.x(), uv.y()) - x).norm(), 0.0, 1e-9 * r) << "longitude " << theta;
    }
}

// A sewn corner (faces 2e-4 apart) 9e-5 from a sphere's pole: its nearest foot lies
// at another longitude, but the point is as good as at the pole, so the meridian's
// edge must keep its own longitude there (with further starts taken for every point
// not exactly on the surface, the edge swerved round the pole and the box of sewn
// patches had 16 open edges).
TEST(SurfaceProjector, PointAHairOffAPoleKeepsTheLongitudeOfItsNeighbour) {
    const double R = 5;
    const NurbsSurface sphere = unit_sphere(R);
    const SurfaceProjector projector(sphere);
    const Eigen::Vector3d x = on_sphere(R + 2e-4, 2.935, -kPi / 2 + 9e-5 / R);
    const Eigen::Vector2d near(0.0, -1.2);  // up the meridian at longitude 0
    const Eigen::Vector2d uv = projector.invert(x, &near);
    EXPECT_NEAR(uv.x(), 0.0, 1e-9);
    EXPECT_LT((sphere.evaluate(uv.x(), uv.y()) - x).norm(), 1e-3);
}

}  // namespace
}  // namespace trimkit::geom
