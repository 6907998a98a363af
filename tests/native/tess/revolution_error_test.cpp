#include "tess/revolution_error.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <set>

#include "geom/analytic_surfaces.h"
#include "surface_test_support.h"
#include "tess/bezier_patch.h"
#include "tess/kd_subdivision.h"
#include "tess/tessellate_face.h"

namespace trimkit::tess {
namespace {

const Eigen::Vector3d kOrigin(1.0, -2.0, 0.5);
const Eigen::Vector3d kAxis = Eigen::Vector3d(1.0, 2.0, 2.0).normalized();
const Eigen::Vector3d kRef(0.0, 1.0, -1.0);  // orthogonal to kAxis

geom::NurbsSurface cylinder(double r) { return geom::cylinder_patch(kOrigin, kAxis, kRef, r, 0, 2 * M_PI, 0, 3); }
geom::NurbsSurface cone() { return geom::cone_patch(kOrigin, kAxis, kRef, 0.5, 0.4, 0, 2 * M_PI, 0, 2); }
geom::NurbsSurface sphere() { return geom::sphere_patch(kOrigin, kAxis, kRef, 1.5, 0, 2 * M_PI, -M_PI / 2, M_PI / 2); }
geom::NurbsSurface torus() { return geom::torus_patch(kOrigin, kAxis, kRef, 3.0, 1.0, 0, 2 * M_PI, -M_PI, M_PI); }

// (rho, z) about the test axis.
Eigen::Vector2d meridian(const Eigen::Vector3d& P) {
    const Eigen::Vector3d d = P - kOrigin;
    const double z = d.dot(kAxis);
    return {(d - z * kAxis).norm(), z};
}

// Exact distances to the test surfaces (closed forms).
double cylinder_distance(const Eigen::Vector3d& P, double r) { return std::abs(meridian(P).x() - r); }
double cone_distance(const Eigen::Vector3d& P) {
    // Meridian rho = 0.5 + z tan(0.4): distance to that line in (rho, z).
    const Eigen::Vector2d m = meridian(P);
    return std::abs(m.x() - 0.5 - m.y() * std::tan(0.4)) * std::cos(0.4);
}
double sphere_distance(const Eigen::Vector3d& P) { return std::abs((P - kOrigin).norm() - 1.5); }
double torus_distance(const Eigen::Vector3d& P) {
    const Eigen::Vector2d m = meridian(P);
    return std::abs(std::hypot(m.x() - 3.0, m.y()) - 1.0);
}

TEST(RevolutionShape, FindsAxisAndMeridianOfTheAnalyticKinds) {
    const auto cyl = revolution_shape(cylinder(2.0), "cylinder");
    ASSERT_TRUE(cyl);
    EXPECT_EQ(cyl->angle_dir, 0);
    EXPECT_FALSE(cyl->circle_meridian);
    EXPECT_NEAR(std::abs(cyl->axis.dot(kAxis)), 1.0, 1e-12);
    EXPECT_NEAR(meridian(cyl->origin).x(), 0.0, 1e-9);

    const auto sph = revolution_shape(sphere(), "sphere");
    ASSERT_TRUE(sph);
    EXPECT_TRUE(sph->circle_meridian);
    EXPECT_NEAR(sph->radius, 1.5, 1e-9);
    const auto tor = revolution_shape(torus(), "torus");
    ASSERT_TRUE(tor);
    EXPECT_TRUE(tor->circle_meridian);
    EXPECT_NEAR(tor->radius, 1.0, 1e-9);
    EXPECT_NEAR(tor->centre.x(), 3.0, 1e-9);
    EXPECT_TRUE(revolution_shape(cone(), "cone"));

    // A "cylinder" squashed into an elliptic one is not recognised, by kind or net.
    geom::NurbsSurface squashed = cylinder(2.0);
    std::vector<Eigen::Vector3d> P = squashed.points();
    for (Eigen::Vector3d& p : P) p.x() *= 1.01;
    squashed = geom::NurbsSurface(squashed.degree_u(), squashed.degree_v(), squashed.knots_u(), squashed.knots_v(),
                                  squashed.count_u(), squashed.count_v(), P, squashed.weights());
    EXPECT_FALSE(revolution_shape(squashed, "cylinder"));
    EXPECT_FALSE(revolution_shape(squashed, "bspline"));
    // A polynomial patch is never taken for one.
    EXPECT_FALSE(revolution_shape(test::bicubic_patch(), "bspline"));
}

// B-spline faces that are exact surfaces of revolution are proved so by their
// control nets, whatever the file calls them; the meridian and axis are the same.
TEST(RevolutionShape, ControlNetProvesRationalBsplineCylindersAndTori) {
    const auto cyl = revolution_shape(cylinder(2.0), "bspline");
    ASSERT_TRUE(cyl);
    EXPECT_FALSE(cyl->circle_meridian);
    EXPECT_NEAR(std::abs(cyl->axis.dot(kAxis)), 1.0, 1e-12);
    const auto tor = revolution_shape(torus(), "bspline");
    ASSERT_TRUE(tor);
    EXPECT_TRUE(tor->circle_meridian);
    EXPECT_NEAR(tor->radius, 1.0, 1e-9);
    EXPECT_NEAR(tor->centre.x(), 3.0, 1e-9);
    const auto sph = revolution_shape(sphere(), "bezier");
    ASSERT_TRUE(sph);
    EXPECT_NEAR(sph->radius, 1.5, 1e-9);
    EXPECT_TRUE(revolution_shape(cone(), "bspline"));
    // One weight moved off the circle condition: not a circle any more.
    std::vector<double> w = cyl ? cylinder(2.0).weights() : std::vector<double>{};
    w[2] *= 1.001;
    const geom::NurbsSurface c = cylinder(2.0);
    EXPECT_FALSE(revolution_shape(geom::NurbsSurface(c.degree_u(), c.degree_v(), c.knots_u(), c.knots_v(), c.count_u(),
                                                     c.count_v(), c.points(), w),
                                  "bspline"));
}

// The cell count of a cylinder is the sagitta formula's: each 90-degree Bezier span
// needs k = ceil((pi/2) / theta_max) strips, theta_max = 2 acos(1 - T / r), and no
// split along the rulings.
TEST(RevolutionError, CylinderCellsAreTheSagittaFormulasStrips) {
    for (double r : {0.9, 2.0, 37.0}) {
        const geom::NurbsSurface S = cylinder(r);
        const auto shape = revolution_shape(S, "cylinder");
        ASSERT_TRUE(shape);
        const double T = 0.008;
        const double theta_max = 2.0 * std::acos(1.0 - (T - shape->slack) / r);
        const int k = static_cast<int>(std::ceil((M_PI / 2) / theta_max));
        const Eigen::AlignedBox2d box(Eigen::Vector2d(0, 0), Eigen::Vector2d(2 * M_PI, 3));
        const CellGrid exact = kd_subdivision(S, box, T, ErrorMode::kGuaranteed, &*shape);
        EXPECT_EQ(exact.cells.size(), 4u * k) << "r = " << r;
        for (const Cell& c : exact.cells) EXPECT_EQ(c.v1 - c.v0, 3.0);
        const CellGrid generic = kd_subdivision(S, box, T, ErrorMode::kGuaranteed);
        EXPECT_GT(generic.cells.size(), exact.cells.size()) << "r = " << r;
    }
}

// Triangles of random points of S inside each cell stay within the cell's bound of
// the exact surface (closed-form distance), and the bound is attained on a
// cylinder (the chord's midpoint).
template <class Distance>
void expect_bound_holds(const geom::NurbsSurface& S, const char* kind, double T, const Distance& distance,
                        double tight_share) {
    const auto shape = revolution_shape(S, kind);
    ASSERT_TRUE(shape) << kind;
    const auto [u0, u1] = S.domain_u();
    const auto [v0, v1] = S.domain_v();
    const Eigen::AlignedBox2d box(Eigen::Vector2d(u0, v0), Eigen::Vector2d(u1, v1));
    const CellGrid grid = kd_subdivision(S, box, T, ErrorMode::kGuaranteed, &*shape);
    std::vector<BezierPatch> patches;
    for (const geom::NurbsSurface& b : S.bezier_patches()) patches.push_back(bezier_patch(b));
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    double worst_share = 0.0;
    for (const Cell& c : grid.cells) {
        const BezierPatch* owner = nullptr;
        for (const BezierPatch& p : patches)
            if (c.u0 >= p.u0 && c.u1 <= p.u1 && c.v0 >= p.v0 && c.v1 <= p.v1) owner = &p;
        ASSERT_NE(owner, nullptr);
        const double bound = revolution_error(*shape, restrict_patch(*owner, c.u0, c.u1, c.v0, c.v1), T).bound;
        ASSERT_LE(bound, T);
        auto at = [&](double a, double b) { return S.evaluate(c.u0 + a * (c.u1 - c.u0), c.v0 + b * (c.v1 - c.v0)); };
        // The two corner triangles' edge midpoints, then random triangles.
        const Eigen::Vector3d mids[] = {0.5 * (at(0, 0) + at(1, 0)), 0.5 * (at(0, 1) + at(1, 1)),
                                        0.5 * (at(0, 0) + at(0, 1)), 0.5 * (at(1, 0) + at(0, 1))};
        for (const Eigen::Vector3d& P : mids)
            worst_share = std::max(worst_share, distance(P) / bound);
        for (int trial = 0; trial < 20; ++trial) {
            const Eigen::Vector3d A = at(unit(random), unit(random)), B = at(unit(random), unit(random)),
                                  C = at(unit(random), unit(random));
            double l0 = unit(random), l1 = unit(random) * (1 - l0);
            const Eigen::Vector3d P = l0 * A + l1 * B + (1 - l0 - l1) * C;
            EXPECT_LE(distance(P), bound) << kind;
        }
    }
    EXPECT_GE(worst_share, tight_share) << kind;
    EXPECT_LE(worst_share, 1.0) << kind;
}

TEST(RevolutionError, BoundHoldsOnEveryKindAndIsTightOnCylinders) {
    expect_bound_holds(cylinder(2.0), "cylinder", 0.01, [](const Eigen::Vector3d& P) { return cylinder_distance(P, 2.0); },
                       0.999);
    expect_bound_holds(cone(), "cone", 0.01, cone_distance, 0.9);
    expect_bound_holds(sphere(), "sphere", 0.01, sphere_distance, 0.5);
    expect_bound_holds(torus(), "torus", 0.01, torus_distance, 0.5);
}

// A whole cylinder face: the mesh stays within T of the exact cylinder and spends
// most of it (the generic rational bound's cells are compared in
// CylinderCellsAreTheSagittaFormulasStrips). The circles have 24 chords (sagitta
// 0.77 T), coarser than the cells (0.8 T at most: 0.27 rad), so the cells split
// between the circles' points and their bound is what the mesh spends; finer circles
// would bound it instead (CylinderCellsMeetTheCirclesAtTheirPoints).
TEST(RevolutionError, CylinderFaceSpendsTheTolerance) {
    const double r = 0.9, T = 0.01;
    geom::Face face = test::face_of(cylinder(r));
    const std::vector<TrimPolygon> loops = {test::rectangle_loop(face.surface, 0, 2 * M_PI, 0, 3, 24)};
    TessellationOptions options;
    options.tolerance = T;
    face.surface_kind = "cylinder";
    const mesh::Mesh exact = tessellate_face(face, loops, options, 0);
    double worst = 0.0;
    for (const auto& t : exact.triangles)
        for (int a = 0; a <= 8; ++a)
            for (int b = 0; a + b <= 8; ++b) {
                const Eigen::Vector3d P = (a * exact.positions[t[0]] + b * exact.positions[t[1]] +
                                           (8 - a - b) * exact.positions[t[2]]) / 8.0;
                worst = std::max(worst, cylinder_distance(P, r));
            }
    EXPECT_LE(worst, T);
    EXPECT_GE(worst, 0.6 * T);
}

// A cylinder between two circles given as polylines of n chords each: the cells'
// splits along the rulings move onto the circles' points (kd_subdivision), so no cell
// line crosses a chord. Every vertex is then a point of a circle, on the cylinder
// (a crossing would sit on a chord, inside it by up to the chord's sagitta), and the
// face is the loop's polygon alone. Without the move, the cells (about 30 around at this
// T) put a crossing on each circle at every cell line (286 triangles, not 254).
TEST(RevolutionError, CylinderCellsMeetTheCirclesAtTheirPoints) {
    const double r = 0.9, T = 0.01;
    constexpr int n = 64;
    geom::Face face = test::face_of(cylinder(r));
    face.surface_kind = "cylinder";
    const std::vector<TrimPolygon> loops = {test::rectangle_loop(face.surface, 0, 2 * M_PI, 0, 3, n)};
    TessellationOptions options;
    options.tolerance = T;
    const mesh::Mesh m = tessellate_face(face, loops, options, 0);
    std::set<std::array<double, 2>> on_circles;  // (z, u) of the distinct vertices
    for (std::size_t v = 0; v < m.positions.size(); ++v) {
        const Eigen::Vector3d& P = m.positions[v];
        EXPECT_NEAR(meridian(P).x(), r, 1e-12) << P.transpose();
        const double z = meridian(P).y();
        if (std::abs(z) < 1e-12 || std::abs(z - 3.0) < 1e-12) on_circles.insert({std::round(z), m.uvs[v].x()});
    }
    // The loop's 4 n points and no other: a polygon of V vertices makes V - 2 triangles.
    EXPECT_EQ(m.triangle_count(), 4u * n - 2u);
    // n + 1 points on each circle (u = 0 and u = 2 pi are the seam's two sides).
    EXPECT_EQ(on_circles.size(), 2u * (n + 1));
}

}  // namespace
}  // namespace trimkit::tess
