// trim_area_loss: the area between a trim polyline's 3D chords and S(c(t)), signed by
// the region's side (issue 9: OCC26308-Face.stp's mesh was 0.33 % short along a chord
// that is straight in (u,v) but bows in 3D).
#include <gtest/gtest.h>

#include <cmath>

#include "geom/analytic_surfaces.h"
#include "geom/nurbs_curve.h"
#include "geom/nurbs_surface.h"
#include "geom/face.h"
#include "geom/model.h"
#include "tess/tessellate_model.h"
#include "tess/trim_area_loss.h"

namespace trimkit::tess {
namespace {

// A polyline of c's end points only.
TrimPolyline ends_of(const geom::NurbsSurface& S, const geom::NurbsCurve2d& c) {
    TrimPolyline p;
    const auto [t0, t1] = c.domain();
    for (double t : {t0, t1}) {
        const Eigen::Vector2d uv = c.evaluate(t);
        p.points.push_back({uv, S.evaluate(uv.x(), uv.y()), t});
    }
    return p;
}

// The plane S(u,v) = (u, v, 0) on [-1, 1] x [-1, 1].
geom::NurbsSurface flat() {
    return geom::NurbsSurface(1, 1, {-1, -1, 1, 1}, {-1, -1, 1, 1}, 2, 2,
                              {{-1, -1, 0}, {-1, 1, 0}, {1, -1, 0}, {1, 1, 0}});
}

TEST(TrimAreaLoss, ParabolicArcOverItsChordIsTwoThirdsChordTimesSagitta) {
    // c(t) = (t, h (1 - t²)) for t in [-1, 1] (Bezier control points (-1, 0), (0, 2h),
    // (1, 0)): the segment over the chord from (-1, 0) to (1, 0) has area 4h/3.
    const double h = 0.1;
    const geom::NurbsSurface S = flat();
    const geom::NurbsCurve2d c(2, {-1, -1, -1, 1, 1, 1}, {{-1, 0}, {0, 2 * h}, {1, 0}});
    const TrimPolyline chord = ends_of(S, c);
    // The arc bulges to the left (+y) of the chord running +x: into a region on the
    // left (the mesh has the segment the face lacks: a gain), away from one on the right.
    EXPECT_NEAR(trim_area_loss(S, c, chord, true), -4.0 * h / 3.0, 1e-12);
    EXPECT_NEAR(trim_area_loss(S, c, chord, false), 4.0 * h / 3.0, 1e-12);
}

TEST(TrimAreaLoss, ChordStraightInUvThatBowsIn3dCounts) {
    // S(u,v) = (u, v + k u², 0) on [-1, 1] x [0, 1]: the iso-line v = 0 is straight in
    // (u,v) and the parabola y = k x² in 3D, k below the chord from (-1, k) to (1, k).
    const double k = 0.05;
    const geom::NurbsSurface S(2, 1, {-1, -1, -1, 1, 1, 1}, {0, 0, 1, 1}, 3, 2,
                               {{-1, k, 0}, {-1, 1 + k, 0}, {0, -k, 0}, {0, 1 - k, 0}, {1, k, 0}, {1, 1 + k, 0}});
    ASSERT_NEAR(S.evaluate(0.0, 0.0).y(), 0.0, 1e-15);
    const geom::NurbsCurve2d c(1, {-1, -1, 1, 1}, {{-1, 0}, {1, 0}});
    // The region (v > 0) is left of the polyline; the curve bows away from it (-y).
    EXPECT_NEAR(trim_area_loss(S, c, ends_of(S, c), true), 4.0 * k / 3.0, 1e-12);
}

TEST(TrimAreaLoss, ParallelCircleOfACylinderBowsOutOfTheSurfaceAndLosesNothing) {
    // A quarter of the unit cylinder, bounded below by the arc z = 0 from angle 0 to
    // pi/2: straight in (u,v), and in 3D the arc bulges from its chord by 1 - cos(pi/4)
    // along the surface normal only. The region above keeps its whole (u,v) area; the
    // triangles' sag is cell_area_loss's. (On a surface of revolution whose profile
    // slopes, the next test, part of the bulge lies in the surface.)
    const geom::NurbsSurface S = geom::cylinder_patch(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(),
                                                      Eigen::Vector3d::UnitX(), 1.0, 0.0, M_PI / 2, 0.0, 1.0);
    const auto [u0, u1] = S.domain_u();
    const auto [v0, v1] = S.domain_v();
    const geom::NurbsCurve2d bottom(1, {0, 0, 1, 1}, {{u0, v0}, {u1, v0}});
    const TrimPolyline chord = ends_of(S, bottom);
    ASSERT_NEAR((chord.points[1].xyz - chord.points[0].xyz).norm(), std::sqrt(2.0), 1e-12);
    EXPECT_NEAR(trim_area_loss(S, bottom, chord, true), 0.0, 1e-12);
    EXPECT_NEAR(trim_area_loss(S, bottom, chord, false), 0.0, 1e-12);
}

TEST(TrimAreaLoss, ParallelCircleOfAConeCountsOnlyTheBulgeAlongTheSurface) {
    // A quarter of a cone narrowing upwards (semi-angle -pi/6, radius 1 at v = 0),
    // bounded below by its parallel circle from angle 0 to pi/2. The arc bulges from
    // its chord by s = 1 - cos(pi/4) away from the axis; within the surface that is
    // s sin(pi/6) down the meridian, away from the region above: a loss of
    // 2/3 x chord x s sin(pi/6) (the whole s, as before, is 2x that).
    const double alpha = -M_PI / 6;
    const geom::NurbsSurface S = geom::cone_patch(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(),
                                                  Eigen::Vector3d::UnitX(), 1.0, alpha, 0.0, M_PI / 2, 0.0, 0.5);
    const auto [u0, u1] = S.domain_u();
    const auto [v0, v1] = S.domain_v();
    const geom::NurbsCurve2d bottom(1, {0, 0, 1, 1}, {{u0, v0}, {u1, v0}});
    const double expected = 2.0 / 3.0 * std::sqrt(2.0) * (1.0 - std::cos(M_PI / 4)) * std::sin(-alpha);
    EXPECT_NEAR(trim_area_loss(S, bottom, ends_of(S, bottom), true), expected, 1e-9);
    EXPECT_NEAR(trim_area_loss(S, bottom, ends_of(S, bottom), false), -expected, 1e-9);
}

// One face on S(u,v) = (u, v + k u² (1 - v), 0), (u,v) in [-1, 1] x [0, 1]: bounded
// by the parabola y = k x², the lines x = ±1 and y = 1. |Su x Sv| = 1 - k u², so
// its area is 2 - 2k/3; the bottom edge is straight in (u,v) and bows k in 3D.
geom::Model bowed_face(double k) {
    geom::Model model;
    geom::Face face;
    face.surface = geom::NurbsSurface(2, 1, {-1, -1, -1, 1, 1, 1}, {0, 0, 1, 1}, 3, 2,
                                      {{-1, k, 0}, {-1, 1, 0}, {0, -k, 0}, {0, 1, 0}, {1, k, 0}, {1, 1, 0}});
    face.loops.push_back(geom::natural_boundary_loop(face.surface));
    model.faces.push_back(face);
    return model;
}

TEST(TrimAreaLoss, ModelWhoseChordsLoseAreaIsMeshedWithFinerTrims) {
    // Trims at 0.1 take the bottom edge as one chord (its Bezier control polygon is 2k
    // off it): 4k/3 lost, 0.67 % of the area, within the 16x finer trims' reach.
    const double k = 0.01;
    TessellationOptions options;
    options.tolerance = 0.1 / (kTrimToleranceShare * (1.0 - kWeldShare));
    options.threads = 1;
    const TessellationResult r = tessellate_model(bowed_face(k), options);
    ASSERT_TRUE(r.failed_faces.empty());
    bool finer = false;
    for (const std::string& w : r.warnings) finer = finer || w.find("meshed again with finer trims") != std::string::npos;
    EXPECT_TRUE(finer);
    const double exact = 2.0 - 2.0 * k / 3.0;
    EXPECT_NEAR(mesh::surface_area(r.mesh) / exact, 1.0, 1e-3);
}

}  // namespace
}  // namespace trimkit::tess
