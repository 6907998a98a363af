// Tests for geom/nurbs_surface.h: an exact rational sphere, derivatives against
// finite differences, knot insertion and splitting keep the shape, normals at
// degenerate points, validation.
#include "geom/nurbs_surface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "geom/analytic_surfaces.h"
#include "geom/error.h"
#include "geom/knot_vector.h"
#include "test_support.h"

namespace trimkit::geom {
namespace {

const double kHalfSqrt2 = std::sqrt(2.0) / 2.0;

// Degree 3 x 2 on [0,1] x [2,5], 6 x 5 points; weights in [0.5, 2] if rational.
NurbsSurface sample_surface(bool rational, double scale = 1.0,
                            const Eigen::Vector3d& offset = Eigen::Vector3d::Zero()) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> jitter(-0.4, 0.4), weight(0.5, 2.0);
    std::vector<Eigen::Vector3d> P;
    std::vector<double> w;
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 5; ++j) {
            P.push_back(offset + scale * Eigen::Vector3d(i + jitter(rng), j + jitter(rng),
                                                         std::sin(i + 2.0 * j) + jitter(rng)));
            w.push_back(weight(rng));
        }
    return NurbsSurface(3, 2, {0, 0, 0, 0, 0.3, 0.6, 1, 1, 1, 1}, {2, 2, 2, 3, 4, 5, 5, 5}, 6, 5,
                        P, rational ? w : std::vector<double>{});
}

// Sphere of radius r about c as the tensor product of a half circle (u, from the
// south pole to the north pole in the (rho, z) plane) and a full circle (v, about
// the z axis), both rational quadratics with weights 1, sqrt(2)/2 ([PT] Sec. 8.5).
NurbsSurface sphere(double r, const Eigen::Vector3d& c = Eigen::Vector3d::Zero()) {
    const double s = kHalfSqrt2;
    const double rho[5] = {0, r, r, r, 0}, z[5] = {-r, -r, 0, r, r};
    const double wm[5] = {1, s, 1, s, 1};
    const double x[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1}, y[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
    const double wc[9] = {1, s, 1, s, 1, s, 1, s, 1};
    std::vector<Eigen::Vector3d> P;
    std::vector<double> w;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 9; ++j) {
            P.push_back(c + Eigen::Vector3d(rho[i] * x[j], rho[i] * y[j], z[i]));
            w.push_back(wm[i] * wc[j]);
        }
    return NurbsSurface(2, 2, {0, 0, 0, 0.5, 0.5, 1, 1, 1},
                        {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, 5, 9, P, w);
}

// n x n parameter grid over the surface's domain (including its edges).
std::vector<std::pair<double, double>> grid(const NurbsSurface& S, int n) {
    const auto [u0, u1] = S.domain_u();
    const auto [v0, v1] = S.domain_v();
    std::vector<std::pair<double, double>> uv;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            uv.emplace_back(u0 + (u1 - u0) * i / (n - 1.0), v0 + (v1 - v0) * j / (n - 1.0));
    return uv;
}

// 50 pseudo-random parameter points, plus the four corners.
std::vector<std::pair<double, double>> random_params(const NurbsSurface& S) {
    std::mt19937 rng(3);
    const auto [u0, u1] = S.domain_u();
    const auto [v0, v1] = S.domain_v();
    std::uniform_real_distribution<double> U(u0, u1), V(v0, v1);
    std::vector<std::pair<double, double>> uv{{u0, v0}, {u1, v0}, {u0, v1}, {u1, v1}};
    for (int k = 0; k < 50; ++k) uv.emplace_back(U(rng), V(rng));
    return uv;
}

double max_distance(const NurbsSurface& a, const NurbsSurface& b) {
    double worst = 0.0;
    for (auto [u, v] : random_params(a))
        worst = std::max(worst, (a.evaluate(u, v) - b.evaluate(u, v)).norm());
    return worst;
}

std::string error_message(int pu, int pv, std::vector<double> U, std::vector<double> V, int nu,
                          int nv, std::vector<Eigen::Vector3d> P, std::vector<double> w = {}) {
    try {
        NurbsSurface S(pu, pv, std::move(U), std::move(V), nu, nv, std::move(P), std::move(w));
    } catch (const InvalidInput& e) {
        return e.what();
    }
    return "";
}

TEST(NurbsSurface, InterpolatesCornerControlPoints) {
    const NurbsSurface S = sample_surface(true);
    EXPECT_NEAR((S.evaluate(0, 2) - S.point(0, 0)).norm(), 0.0, 1e-14);
    EXPECT_NEAR((S.evaluate(1, 2) - S.point(5, 0)).norm(), 0.0, 1e-14);
    EXPECT_NEAR((S.evaluate(0, 5) - S.point(0, 4)).norm(), 0.0, 1e-14);
    EXPECT_NEAR((S.evaluate(1, 5) - S.point(5, 4)).norm(), 0.0, 1e-14);
    EXPECT_EQ(S.domain_v(), std::make_pair(2.0, 5.0));
}

TEST(NurbsSurface, SphereLiesAtRadius) {
    for (double r : {1.0, 2.5, 1e6, 1e-6}) {
        const Eigen::Vector3d c = r * Eigen::Vector3d(1, -2, 3);
        const NurbsSurface S = sphere(r, c);
        for (auto [u, v] : grid(S, 41)) {
            const Eigen::Vector3d P = S.evaluate(u, v);
            EXPECT_TRUE(test::is_finite(P));
            EXPECT_NEAR((P - c).norm(), r, 1e-12 * r) << "r = " << r << " at " << u << ", " << v;
        }
        EXPECT_NEAR((S.evaluate(0.5, 0.0) - c - Eigen::Vector3d(r, 0, 0)).norm(), 0.0, 1e-12 * r);
        EXPECT_NEAR((S.evaluate(1.0, 0.3) - c - Eigen::Vector3d(0, 0, r)).norm(), 0.0, 1e-12 * r);
    }
}

void expect_derivatives_match_differences(const NurbsSurface& S, double tolerance) {
    const auto [u0, u1] = S.domain_u();
    const auto [v0, v1] = S.domain_v();
    const double hu = 1e-5 * (u1 - u0), hv = 1e-5 * (v1 - v0);
    for (int i = 1; i < 12; ++i)
        for (int j = 1; j < 12; ++j) {
            const double u = u0 + (u1 - u0) * (i + 0.13) / 12.0;
            const double v = v0 + (v1 - v0) * (j + 0.29) / 12.0;
            const SurfaceDerivatives D = S.derivatives(u, v);
            const SurfaceDerivatives Dup = S.derivatives(u + hu, v), Dum = S.derivatives(u - hu, v);
            const SurfaceDerivatives Dvp = S.derivatives(u, v + hv), Dvm = S.derivatives(u, v - hv);
            const Eigen::Vector3d Su = (S.evaluate(u + hu, v) - S.evaluate(u - hu, v)) / (2 * hu);
            const Eigen::Vector3d Sv = (S.evaluate(u, v + hv) - S.evaluate(u, v - hv)) / (2 * hv);
            const Eigen::Vector3d Suu = (Dup.Su - Dum.Su) / (2 * hu);
            const Eigen::Vector3d Suv = (Dvp.Su - Dvm.Su) / (2 * hv);
            const Eigen::Vector3d Svu = (Dup.Sv - Dum.Sv) / (2 * hu);
            const Eigen::Vector3d Svv = (Dvp.Sv - Dvm.Sv) / (2 * hv);
            const auto near = [&](const Eigen::Vector3d& exact, const Eigen::Vector3d& fd,
                                  const char* what) {
                EXPECT_NEAR((exact - fd).norm(), 0.0, tolerance * std::max(1.0, exact.norm()))
                    << what << " at (" << u << ", " << v << ")";
            };
            EXPECT_NEAR((D.S - S.evaluate(u, v)).norm(), 0.0, 1e-14 * std::max(1.0, D.S.norm()));
            near(D.Su, Su, "Su");
            near(D.Sv, Sv, "Sv");
            near(D.Suu, Suu, "Suu");
            near(D.Suv, Suv, "Suv");
            near(D.Suv, Svu, "Svu");
            near(D.Svv, Svv, "Svv");
        }
}

TEST(NurbsSurface, DerivativesMatchCentralDifferences) {
    expect_derivatives_match_differences(sample_surface(false), 1e-6);
    expect_derivatives_match_differences(sample_surface(true), 1e-6);
    expect_derivatives_match_differences(sphere(1.0), 1e-6);
}

TEST(NurbsSurface, SecondDerivativesMatchSecondDifferences) {
    const NurbsSurface S = sample_surface(true);
    const double h = 1e-4;
    for (auto [u, v] : {std::pair{0.2, 2.5}, {0.45, 3.7}, {0.8, 4.6}}) {
        const SurfaceDerivatives D = S.derivatives(u, v);
        const Eigen::Vector3d Suu =
            (S.evaluate(u + h, v) - 2 * S.evaluate(u, v) + S.evaluate(u - h, v)) / (h * h);
        const Eigen::Vector3d Svv =
            (S.evaluate(u, v + h) - 2 * S.evaluate(u, v) + S.evaluate(u, v - h)) / (h * h);
        const Eigen::Vector3d Suv = (S.evaluate(u + h, v + h) - S.evaluate(u + h, v - h) -
                                     S.evaluate(u - h, v + h) + S.evaluate(u - h, v - h)) /
                                    (4 * h * h);
        EXPECT_NEAR((D.Suu - Suu).norm(), 0.0, 1e-4 * std::max(1.0, D.Suu.norm()));
        EXPECT_NEAR((D.Svv - Svv).norm(), 0.0, 1e-4 * std::max(1.0, D.Svv.norm()));
        EXPECT_NEAR((D.Suv - Suv).norm(), 0.0, 1e-4 * std::max(1.0, D.Suv.norm()));
    }
}

TEST(NurbsSurface, SphereNormalIsRadialIncludingPoles) {
    for (double r : {1.0, 1e6, 1e-6}) {
        const Eigen::Vector3d c = r * Eigen::Vector3d(2, 0, -1);
        const NurbsSurface S = sphere(r, c);
        // Su x Sv orientation, taken at the equator.
        const double sign = S.normal(0.5, 0.1).dot((S.evaluate(0.5, 0.1) - c) / r);
        EXPECT_NEAR(std::abs(sign), 1.0, 1e-12);
        for (auto [u, v] : grid(S, 21)) {  // includes both poles (u = 0, u = 1)
            const Eigen::Vector3d n = S.normal(u, v);
            EXPECT_NEAR(n.norm(), 1.0, 1e-12);
            const Eigen::Vector3d radial = (S.evaluate(u, v) - c) / r;
            EXPECT_NEAR(n.dot(radial), sign, 1e-9) << "r = " << r << " at " << u << ", " << v;
        }
    }
}

TEST(NurbsSurface, NormalAtCornerWithParallelDerivativesUsesInterior) {
    // Bilinear patch in z = 0 whose Su and Sv are parallel at (0, 0).
    const NurbsSurface S(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2,
                         {{0, 0, 0}, {2, 0, 0}, {1, 0, 0}, {1, 1, 0}});
    const SurfaceDerivatives D = S.derivatives(0, 0);
    EXPECT_NEAR(D.Su.cross(D.Sv).norm(), 0.0, 1e-15);
    const Eigen::Vector3d interior = S.normal(0.5, 0.5);
    EXPECT_NEAR(std::abs(interior.z()), 1.0, 1e-15);
    EXPECT_NEAR((S.normal(0, 0) - interior).norm(), 0.0, 1e-12);
}

TEST(NurbsSurface, NormalThrowsWhenNoDirectionExists) {
    const NurbsSurface S(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2,
                         std::vector<Eigen::Vector3d>(4, Eigen::Vector3d(1, 2, 3)));
    EXPECT_THROW(S.normal(0.5, 0.5), NumericalFailure);
    // A line-shaped surface: every point degenerate.
    const NurbsSurface L(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2,
                         {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}});
    EXPECT_THROW(L.normal(0.3, 0.6), NumericalFailure);
}

TEST(NurbsSurface, KnotInsertionKeepsShape) {
    for (bool rational : {false, true}) {
        const NurbsSurface S = sample_surface(rational);
        for (double u : {0.0, 0.1, 0.3, 0.77, 1.0})
            for (int times : {1, 2, 4}) {
                const NurbsSurface T = S.insert_knot_u(u, times);
                EXPECT_LT(max_distance(S, T), 1e-12) << "u = " << u << ", times " << times;
                EXPECT_EQ(T.count_u() * T.count_v(), static_cast<int>(T.points().size()));
                EXPECT_EQ(T.knots_u().size(), static_cast<size_t>(T.count_u() + 4));
            }
        for (double v : {2.0, 2.2, 3.0, 4.9, 5.0})
            for (int times : {1, 2, 3}) {
                const NurbsSurface T = S.insert_knot_v(v, times);
                EXPECT_LT(max_distance(S, T), 1e-12) << "v = " << v << ", times " << times;
                EXPECT_EQ(T.knots_v().size(), static_cast<size_t>(T.count_v() + 3));
            }
        EXPECT_EQ(S.insert_knot_u(0.5, 2).count_u(), 8);
        EXPECT_EQ(S.insert_knot_v(3.0, 2).count_v(), 6);  // 3.0 already once: capped at p = 2
        EXPECT_THROW(S.insert_knot_u(1.5), InvalidInput);
    }
    const NurbsSurface ball = sphere(3.0);
    EXPECT_LT(max_distance(ball, ball.insert_knot_u(0.3, 2).insert_knot_v(0.6)), 1e-12);
}

TEST(NurbsSurface, BezierPatchesReproduceSurface) {
    for (bool rational : {false, true}) {
        const NurbsSurface S = sample_surface(rational);
        const auto patches = S.bezier_patches();
        const std::vector<double> bu{0, 0.3, 0.6, 1}, bv{2, 3, 4, 5};
        ASSERT_EQ(patches.size(), 9u);
        for (size_t i = 0; i < 3; ++i)
            for (size_t j = 0; j < 3; ++j) {
                const NurbsSurface& B = patches[i * 3 + j];
                EXPECT_EQ(B.count_u(), 4);
                EXPECT_EQ(B.count_v(), 3);
                EXPECT_EQ(B.knots_u(), bezier_knots(3, bu[i], bu[i + 1]));
                EXPECT_EQ(B.knots_v(), bezier_knots(2, bv[j], bv[j + 1]));
                EXPECT_LT(max_distance(B, S), 1e-12);
            }
    }
    const NurbsSurface ball = sphere(1.0);
    const auto patches = ball.bezier_patches();
    ASSERT_EQ(patches.size(), 8u);
    for (const NurbsSurface& B : patches) {
        EXPECT_LT(max_distance(B, ball), 1e-12);
        for (auto [u, v] : grid(B, 7)) EXPECT_NEAR(B.evaluate(u, v).norm(), 1.0, 1e-12);
    }
}

TEST(NurbsSurface, SubSurfaceReproducesPiece) {
    const NurbsSurface S = sample_surface(true);
    const NurbsSurface T = S.sub_surface(0.1, 0.65, 2.5, 4.0);
    EXPECT_EQ(T.domain_u(), std::make_pair(0.1, 0.65));
    EXPECT_EQ(T.domain_v(), std::make_pair(2.5, 4.0));
    EXPECT_LT(max_distance(T, S), 1e-12);
    EXPECT_NEAR((T.point(0, 0) - S.evaluate(0.1, 2.5)).norm(), 0.0, 1e-12);
    EXPECT_LT(max_distance(S.sub_surface(0, 1, 2, 5), S), 1e-12);
    EXPECT_THROW(S.sub_surface(0.5, 0.4, 2, 3), InvalidInput);
    EXPECT_THROW(S.sub_surface(0.1, 0.4, 1, 3), InvalidInput);
}

// sub_surface refines only the rows that support the range (crop_u): a piece inside one
// span, on its knots or at the domain's ends comes out as one Bezier patch that equals S.
TEST(NurbsSurface, SubSurfaceOfOneSpanIsOneBezierPatch) {
    for (bool rational : {false, true}) {
        const NurbsSurface S = sample_surface(rational);  // u knots 0, .3, .6, 1; v 2, 3, 4, 5
        const double ranges[][4] = {{0.35, 0.55, 3.2, 3.8}, {0.3, 0.6, 3, 4}, {0, 0.3, 2, 3},
                                    {0.6, 1, 4, 5}, {0.61, 0.99, 2.01, 2.99}};
        for (const auto& r : ranges) {
            const NurbsSurface T = S.sub_surface(r[0], r[1], r[2], r[3]);
            EXPECT_EQ(T.count_u(), 4);
            EXPECT_EQ(T.count_v(), 3);
            EXPECT_EQ(T.knots_u(), bezier_knots(3, r[0], r[1]));
            EXPECT_EQ(T.knots_v(), bezier_knots(2, r[2], r[3]));
            EXPECT_LT(max_distance(T, S), 1e-12);
        }
        // Across two simple knots in u (0.3, 0.6) and one in v (3): they stay simple,
        // so degree + 1 + 2 rows and degree + 1 + 1 columns.
        const NurbsSurface W = S.sub_surface(0.2, 0.7, 2.5, 3.5);
        EXPECT_EQ(W.count_u(), 3 + 1 + 2);
        EXPECT_EQ(W.count_v(), 2 + 1 + 1);
        EXPECT_LT(max_distance(W, S), 1e-12);
    }
}

TEST(NurbsSurface, SwappedUvExchangesParameters) {
    const NurbsSurface S = sample_surface(true);
    const NurbsSurface T = S.swapped_uv();
    EXPECT_EQ(T.degree_u(), 2);
    EXPECT_EQ(T.count_u(), 5);
    EXPECT_EQ(T.domain_u(), S.domain_v());
    for (auto [u, v] : random_params(S)) {
        EXPECT_NEAR((T.evaluate(v, u) - S.evaluate(u, v)).norm(), 0.0, 1e-14);
        const SurfaceDerivatives a = S.derivatives(u, v), b = T.derivatives(v, u);
        EXPECT_NEAR((a.Su - b.Sv).norm(), 0.0, 1e-12 * std::max(1.0, a.Su.norm()));
        EXPECT_NEAR((a.Suu - b.Svv).norm(), 0.0, 1e-12 * std::max(1.0, a.Suu.norm()));
    }
    EXPECT_EQ(T.swapped_uv().points(), S.points());
}

TEST(NurbsSurface, ControlBoxAndTransform) {
    const NurbsSurface S = sample_surface(true);
    auto box = S.control_box();
    // Rounding of the rational quotient (~1e-16) can land a boundary point just outside.
    box.extend(box.max() + Eigen::Vector3d::Constant(1e-14));
    box.extend(box.min() - Eigen::Vector3d::Constant(1e-14));
    for (auto [u, v] : grid(S, 30)) EXPECT_TRUE(box.contains(S.evaluate(u, v)));
    const Eigen::Affine3d T = Eigen::Translation3d(5, 6, -7) *
                              Eigen::AngleAxisd(1.1, Eigen::Vector3d(0, 1, 1).normalized()) *
                              Eigen::Scaling(3.0);
    const NurbsSurface M = S.transformed(T);
    for (auto [u, v] : random_params(S)) {
        EXPECT_NEAR((M.evaluate(u, v) - T * S.evaluate(u, v)).norm(), 0.0, 1e-12);
        // A rotation and uniform scale carry the normal along.
        EXPECT_NEAR((M.normal(u, v) - T.linear() * S.normal(u, v) / 3.0).norm(), 0.0, 1e-12);
    }
}

TEST(NurbsSurface, HugeAndTinyScales) {
    const NurbsSurface unit = sample_surface(true);
    for (double scale : {1e6, 1e-6}) {
        const Eigen::Vector3d offset = scale * Eigen::Vector3d(-40, 7, 13);
        const NurbsSurface S = sample_surface(true, scale, offset);
        for (auto [u, v] : random_params(S)) {
            const SurfaceDerivatives D = S.derivatives(u, v), E = unit.derivatives(u, v);
            EXPECT_TRUE(test::is_finite(D.Suv));
            EXPECT_NEAR((D.S - (offset + scale * E.S)).norm(), 0.0, 1e-12 * scale * 50);
            EXPECT_NEAR((D.Su - scale * E.Su).norm(), 0.0, 1e-11 * scale * E.Su.norm());
            EXPECT_NEAR((D.Svv - scale * E.Svv).norm(), 0.0,
                        1e-10 * scale * std::max(1.0, E.Svv.norm()));
            EXPECT_NEAR((S.normal(u, v) - unit.normal(u, v)).norm(), 0.0, 1e-9);
        }
        EXPECT_LT(max_distance(S, S.insert_knot_u(0.45, 3).insert_knot_v(3.3, 2)),
                  1e-12 * scale * 50);
    }
}

TEST(NurbsSurface, ValidationErrorsNameTheProblem) {
    using P3 = Eigen::Vector3d;
    const std::vector<P3> P{P3(0, 0, 0), P3(0, 1, 0), P3(1, 0, 0), P3(1, 1, 1)};
    const std::vector<double> K{0, 0, 1, 1};
    EXPECT_EQ(error_message(1, 1, K, K, 2, 2, P), "");

    std::string m = error_message(1, 1, K, K, 2, 3, P);
    EXPECT_NE(m.find("4 control points for a grid of 2 x 3"), std::string::npos) << m;

    std::vector<P3> bad = P;
    bad[3].z() = std::numeric_limits<double>::quiet_NaN();
    m = error_message(1, 1, K, K, 2, 2, bad);
    EXPECT_NE(m.find("point[3] (i = 1, j = 1)"), std::string::npos) << m;
    EXPECT_NE(m.find("finite"), std::string::npos) << m;

    m = error_message(1, 1, K, K, 2, 2, P, {1, 1, -0.5, 1});
    EXPECT_EQ(m, "NurbsSurface: weight[2] = -0.5; rational weights must be finite and > 0");

    m = error_message(10000, 1, K, K, 2, 2, P);
    EXPECT_NE(m.find("degree 10000"), std::string::npos) << m;

    m = error_message(1, 1, K, {0, 0.5, 0.2, 1}, 2, 2, P);
    EXPECT_NE(m.find("v knots"), std::string::npos) << m;
    EXPECT_NE(m.find("knot[2] = 0.2 < knot[1] = 0.5; knots must be non-decreasing"),
              std::string::npos) << m;

    EXPECT_NE(error_message(1, 1, K, K, 2, 2, P, {1, 1, 1}).find("weights"), std::string::npos);
    EXPECT_NE(error_message(2, 1, K, K, 2, 2, P).find("u knots"), std::string::npos);
}

// is_affine: S = a + u b + v c exactly. A plane patch is; a bilinear patch whose four
// points form a planar trapezoid lies in a plane but is not affine in (u,v), and
// neither is the plane with unequal weights or a twisted bilinear patch.
TEST(NurbsSurface, IsAffineOnlyForParallelogramBilinearPatches) {
    const NurbsSurface plane = plane_patch({1, 2, 3}, {2, 0, 1}, {0, 3, -1}, -1.0, 4.0, 0.5, 2.0);
    EXPECT_TRUE(plane.is_affine());
    EXPECT_TRUE(plane.transformed(Eigen::Affine3d(Eigen::Scaling(1e6))).is_affine());
    const std::vector<double> k = {0, 0, 1, 1};
    const NurbsSurface trapezoid(1, 1, k, k, 2, 2, {{0, 0, 0}, {0, 1, 0}, {2, 0, 0}, {1.5, 1, 0}});
    EXPECT_FALSE(trapezoid.is_affine());
    const NurbsSurface twisted(1, 1, k, k, 2, 2, {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0.5}});
    EXPECT_FALSE(twisted.is_affine());
    const NurbsSurface weighted(1, 1, k, k, 2, 2, {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}}, {1, 1, 1, 2});
    EXPECT_FALSE(weighted.is_affine());
    const NurbsSurface elevated(2, 1, {0, 0, 0, 1, 1, 1}, k, 3, 2,
                                {{0, 0, 0}, {0, 1, 0}, {0.5, 0, 0}, {0.5, 1, 0}, {1, 0, 0}, {1, 1, 0}});
    EXPECT_FALSE(elevated.is_affine());  // affine too, but only the one-span bilinear form is recognised
}

}  // namespace
}  // namespace trimkit::geom
