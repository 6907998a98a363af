#include "geom/analytic_surfaces.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "geom/analytic_curves.h"
#include "geom/arc_parameter_map.h"
#include "geom/error.h"

namespace trimkit::geom {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A tilted frame so no test relies on coordinate axes.
const Eigen::Vector3d kAxis = Eigen::Vector3d(1, -2, 2).normalized();
const Eigen::Vector3d kRef = Eigen::Vector3d(2, 1, 0).normalized();  // ⟂ kAxis
const Eigen::Vector3d kY = kAxis.cross(kRef);
const Eigen::Vector3d kCenter(3, -1, 0.5);

// Calls f(native_u, native_v, S) for 100 pseudo-random native parameter pairs,
// mapping each angular coordinate through its ArcParameterMap (null: affine).
void for_samples(const NurbsSurface& s, const ArcParameterMap* mu, const ArcParameterMap* mv,
                 const std::function<void(double, double, const Eigen::Vector3d&)>& f) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto [u0, u1] = s.domain_u();
    const auto [v0, v1] = s.domain_v();
    for (int k = 0; k < 100; ++k) {
        // Native ranges equal the NURBS domains (increasing angles: t = θ at the ends).
        const double a = k == 0 ? u0 : k == 1 ? u1 : u0 + (u1 - u0) * unit(rng);
        const double b = k == 0 ? v0 : k == 1 ? v1 : v0 + (v1 - v0) * unit(rng);
        const double u = mu ? mu->to_nurbs(a) : a;
        const double v = mv ? mv->to_nurbs(b) : b;
        f(a, b, s.evaluate(u, v));
    }
}

Eigen::Vector3d radial(double theta) { return std::cos(theta) * kRef + std::sin(theta) * kY; }

TEST(AnalyticSurfaces, PlanePatchIsTheAffineMap) {
    const Eigen::Vector3d du(1, 2, 0), dv(0, 1, 3);
    NurbsSurface s = plane_patch(kCenter, du, dv, -1, 2, 0.5, 4);
    EXPECT_EQ(s.domain_u(), std::make_pair(-1.0, 2.0));
    EXPECT_EQ(s.domain_v(), std::make_pair(0.5, 4.0));
    for_samples(s, nullptr, nullptr, [&](double u, double v, const Eigen::Vector3d& S) {
        EXPECT_LT((S - (kCenter + u * du + v * dv)).norm(), 1e-14 * 10);
    });
    EXPECT_THROW(plane_patch(kCenter, du, 2 * du, 0, 1, 0, 1), InvalidInput);
    EXPECT_THROW(plane_patch(kCenter, du, dv, 1, 1, 0, 1), InvalidInput);
}

TEST(AnalyticSurfaces, CylinderPatchPointsAreAtTheirAngleAndHeight) {
    for (double scale : {1e-6, 1.0, 1e6}) {
        const double r = 2.5 * scale;
        const Eigen::Vector3d c = scale * kCenter;
        for (auto [t0, t1] : {std::pair{0.0, 2 * kPi}, std::pair{-0.5, 1.0}, std::pair{1.0, 4.5}}) {
            NurbsSurface s = cylinder_patch(c, 3 * kAxis, kRef + kAxis, r, t0, t1, -scale, 2 * scale);
            ArcParameterMap mu(t0, t1);
            EXPECT_EQ(s.domain_u(), std::make_pair(t0, t1));
            EXPECT_EQ(s.domain_v(), std::make_pair(-scale, 2 * scale));
            for_samples(s, &mu, nullptr, [&](double th, double z, const Eigen::Vector3d& S) {
                const Eigen::Vector3d expected = c + z * kAxis + r * radial(th);
                EXPECT_LT((S - expected).norm(), 1e-12 * r);
                const Eigen::Vector3d d = S - c;
                EXPECT_NEAR((d - d.dot(kAxis) * kAxis).norm(), r, 1e-12 * r);
            });
        }
    }
    EXPECT_THROW(cylinder_patch(kCenter, kAxis, kAxis, 1, 0, 1, 0, 1), InvalidInput);
    EXPECT_THROW(cylinder_patch(kCenter, kAxis, kRef, 0, 0, 1, 0, 1), InvalidInput);
    EXPECT_THROW(cylinder_patch(kCenter, kAxis, kRef, 1, 1, 0, 0, 1), InvalidInput);
}

TEST(AnalyticSurfaces, NormalsPointAwayFromTheAxis) {
    NurbsSurface cyl = cylinder_patch(kCenter, kAxis, kRef, 2, 0, 2 * kPi, 0, 1);
    NurbsSurface sph = sphere_patch(kCenter, kAxis, kRef, 2, 0, 2 * kPi, -kPi / 2, kPi / 2);
    for (double th : {0.3, 2.0, 5.0}) {
        EXPECT_GT(cyl.normal(th, 0.5).dot(radial(th)), 0.99);
        EXPECT_GT(sph.normal(th, 0.2).dot(sph.evaluate(th, 0.2) - kCenter), 0);
    }
}

TEST(AnalyticSurfaces, ConePatchRadiusGrowsWithTheSemiAngle) {
    const double r0 = 1.5, beta = 0.4;
    NurbsSurface s = cone_patch(kCenter, kAxis, kRef, r0, beta, 0.2, 5.0, -1.0, 3.0);
    ArcParameterMap mu(0.2, 5.0);
    EXPECT_EQ(s.domain_v(), std::make_pair(-1.0, 3.0));
    for_samples(s, &mu, nullptr, [&](double th, double v, const Eigen::Vector3d& S) {
        const double rho = r0 + v * std::tan(beta);
        EXPECT_LT((S - (kCenter + v * kAxis + rho * radial(th))).norm(), 1e-12 * 5);
        const Eigen::Vector3d d = S - kCenter;
        EXPECT_NEAR((d - d.dot(kAxis) * kAxis).norm(), std::abs(rho), 1e-12 * 5);
    });
    EXPECT_THROW(cone_patch(kCenter, kAxis, kRef, 1, kPi / 2, 0, 1, 0, 1), InvalidInput);
}

TEST(AnalyticSurfaces, SpherePatchPointsAreOnTheSphere) {
    const double r = 4;
    for (auto [p0, p1] : {std::pair{-kPi / 2, kPi / 2}, std::pair{-0.3, 1.2}}) {
        NurbsSurface s = sphere_patch(kCenter, kAxis, kRef, r, -1.0, 4.0, p0, p1);
        ArcParameterMap mu(-1.0, 4.0), mv(p0, p1);
        EXPECT_EQ(s.domain_v(), std::make_pair(p0, p1));
        for_samples(s, &mu, &mv, [&](double th, double ph, const Eigen::Vector3d& S) {
            const Eigen::Vector3d expected =
                kCenter + r * (std::cos(ph) * radial(th) + std::sin(ph) * kAxis);
            EXPECT_LT((S - expected).norm(), 1e-12 * r);
            EXPECT_NEAR((S - kCenter).norm(), r, 1e-12 * r);
        });
    }
    EXPECT_THROW(sphere_patch(kCenter, kAxis, kRef, r, 0, 1, -2.0, 0), InvalidInput);
}

TEST(AnalyticSurfaces, TorusPatchSatisfiesTheImplicitEquation) {
    const double R = 5, r = 1.5;
    NurbsSurface s = torus_patch(kCenter, kAxis, kRef, R, r, 0, 2 * kPi, -kPi, kPi);
    ArcParameterMap mu(0, 2 * kPi), mv(-kPi, kPi);
    for_samples(s, &mu, &mv, [&](double th, double ph, const Eigen::Vector3d& S) {
        const Eigen::Vector3d expected =
            kCenter + (R + r * std::cos(ph)) * radial(th) + r * std::sin(ph) * kAxis;
        EXPECT_LT((S - expected).norm(), 1e-12 * R);
        // (|d|² + R² - r²)² = 4 R² |d_perp|²
        const Eigen::Vector3d d = S - kCenter;
        const double perp2 = (d - d.dot(kAxis) * kAxis).squaredNorm();
        const double lhs = d.squaredNorm() + R * R - r * r;
        EXPECT_NEAR(lhs * lhs, 4 * R * R * perp2, 1e-12 * std::pow(R + r, 4));
    });
}

TEST(AnalyticSurfaces, RevolvedLineIsACone) {
    // Line from radius 1 at height -1 to radius 3 at height 3 (tan β = 0.5), turned
    // about kAxis through kCenter, starting in the kRef direction.
    const Eigen::Vector3d P0 = kCenter - kAxis + 1.5 * kRef, P1 = kCenter + 3 * kAxis + 3.5 * kRef;
    NurbsCurve3d gen = line_segment(P0, P1, -1.0, 3.0);
    NurbsSurface rev = surface_of_revolution(gen, kCenter + 7 * kAxis, 2 * kAxis, 0.5, 5.5);
    NurbsSurface cone = cone_patch(kCenter, kAxis, kRef, 2.0, std::atan(0.5), 0.5, 5.5, -1.0, 3.0);
    EXPECT_EQ(rev.domain_u(), std::make_pair(-1.0, 3.0));
    EXPECT_EQ(rev.domain_v(), std::make_pair(0.5, 5.5));
    ArcParameterMap mv(0.5, 5.5);
    for_samples(rev, nullptr, &mv, [&](double z, double th, const Eigen::Vector3d& S) {
        EXPECT_LT((S - cone.evaluate(mv.to_nurbs(th), z)).norm(), 1e-12 * 4);
        const double rho = 2.0 + 0.5 * z;
        EXPECT_LT((S - (kCenter + z * kAxis + rho * radial(th))).norm(), 1e-12 * 4);
    });
}

TEST(AnalyticSurfaces, RevolvedArcIsATorus) {
    const double R = 4, r = 1;
    NurbsCurve3d gen = circular_arc(kCenter + R * kRef, kRef, kAxis, r, -2.0, 2.5);
    NurbsSurface rev = surface_of_revolution(gen, kCenter, kAxis, 0.0, 2 * kPi);
    ArcParameterMap mu(-2.0, 2.5), mv(0.0, 2 * kPi);
    for_samples(rev, &mu, &mv, [&](double ph, double th, const Eigen::Vector3d& S) {
        const Eigen::Vector3d expected =
            kCenter + (R + r * std::cos(ph)) * radial(th) + r * std::sin(ph) * kAxis;
        EXPECT_LT((S - expected).norm(), 1e-12 * R);
    });
}

TEST(AnalyticSurfaces, TabulatedCylinderTranslatesTheDirectrix) {
    NurbsCurve3d arc = circular_arc(kCenter, kRef, kY, 2.0, 0.5, 3.0);
    const Eigen::Vector3d T(0.5, 1, 2);
    NurbsSurface s = tabulated_cylinder(arc, T, -1.0, 2.0);
    EXPECT_EQ(s.domain_u(), arc.domain());
    for_samples(s, nullptr, nullptr, [&](double u, double v, const Eigen::Vector3d& S) {
        EXPECT_LT((S - (arc.evaluate(u) + v * T)).norm(), 1e-12 * 4);
    });
    EXPECT_THROW(tabulated_cylinder(arc, Eigen::Vector3d::Zero()), InvalidInput);
}

TEST(AnalyticSurfaces, RuledSurfaceBetweenLinesIsBilinear) {
    const Eigen::Vector3d A(0, 0, 0), B(2, 0, 1), C(0, 3, 0), D(1, 2, 4);
    NurbsSurface s = ruled_surface(line_segment(A, B, 5, 7), line_segment(C, D, -1, 0));
    EXPECT_EQ(s.domain_u(), std::make_pair(0.0, 1.0));
    EXPECT_EQ(s.domain_v(), std::make_pair(0.0, 1.0));
    for_samples(s, nullptr, nullptr, [&](double u, double v, const Eigen::Vector3d& S) {
        const Eigen::Vector3d expected =
            (1 - v) * ((1 - u) * A + u * B) + v * ((1 - u) * C + u * D);
        EXPECT_LT((S - expected).norm(), 1e-14 * 10);
    });
}

TEST(AnalyticSurfaces, RuledSurfaceBetweenArcAndCubicIsLinearInV) {
    // Different degrees, knots and weights: v must still be the exact fraction.
    NurbsCurve3d arc = circular_arc(kCenter, kRef, kY, 2.0, 0.3, 4.0);
    std::vector<Eigen::Vector3d> P{{0, 0, 3}, {1, 2, 3}, {2, -1, 3}, {3, 0, 4}, {4, 1, 3}};
    NurbsCurve3d cubic(3, {1, 1, 1, 1, 1.7, 2, 2, 2, 2}, P, {1, 2, 0.5, 1, 1});
    NurbsSurface s = ruled_surface(arc, cubic);
    for_samples(s, nullptr, nullptr, [&](double u, double v, const Eigen::Vector3d& S) {
        const Eigen::Vector3d expected =
            (1 - v) * arc.evaluate(0.3 + 3.7 * u) + v * cubic.evaluate(1 + u);
        EXPECT_LT((S - expected).norm(), 1e-12 * 10);
    });
}

}  // namespace
}  // namespace trimkit::geom
