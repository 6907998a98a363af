// Tests for geom/bezier_triangle.h: Bernstein sum against de Casteljau, corner
// interpolation, derivatives against finite differences, subdivision reproducing
// the parent (acceptance: 1e-12), validation.
#include "geom/bezier_triangle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "geom/error.h"
#include "test_support.h"

namespace trimkit::geom {
namespace {

BezierTriangle random_triangle(int n, unsigned seed, double scale = 1.0) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> c(-1.0, 1.0);
    std::vector<Eigen::Vector3d> P;
    for (int i = n; i >= 0; --i)
        for (int j = n - i; j >= 0; --j)
            P.push_back(scale * Eigen::Vector3d(i + 0.3 * c(rng), j + 0.3 * c(rng), c(rng)));
    return BezierTriangle(n, P);
}

double factorial(int n) { return n <= 1 ? 1.0 : n * factorial(n - 1); }

Eigen::Vector3d bernstein_sum(const BezierTriangle& b, const Eigen::Vector3d& t) {
    const int n = b.degree();
    Eigen::Vector3d s = Eigen::Vector3d::Zero();
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n - i; ++j) {
            const int k = n - i - j;
            s += b.point(i, j) * factorial(n) / (factorial(i) * factorial(j) * factorial(k)) *
                 std::pow(t[0], i) * std::pow(t[1], j) * std::pow(t[2], k);
        }
    return s;
}

Eigen::Vector3d random_bary(std::mt19937& rng) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    double a = u(rng), b = u(rng);
    if (a + b > 1) a = 1 - a, b = 1 - b;
    return {a, b, 1 - a - b};
}

TEST(BezierTriangle, IndexFollowsStorageOrder) {
    // cubic: b300 b210 b201 b120 b111 b102 b030 b021 b012 b003
    const int expected[10][2] = {{3, 0}, {2, 1}, {2, 0}, {1, 2}, {1, 1}, {1, 0}, {0, 3}, {0, 2}, {0, 1}, {0, 0}};
    for (int q = 0; q < 10; ++q) EXPECT_EQ(BezierTriangle::index(3, expected[q][0], expected[q][1]), q);
}

TEST(BezierTriangle, DeCasteljauMatchesBernsteinSum) {
    std::mt19937 rng(3);
    for (int n : {1, 2, 3, 4, 7, 12}) {
        const BezierTriangle b = random_triangle(n, 10 + n);
        for (int s = 0; s < 20; ++s) {
            const Eigen::Vector3d t = random_bary(rng);
            EXPECT_LT((b.evaluate(t) - bernstein_sum(b, t)).norm(), 1e-11 * std::pow(2.0, n)) << n;
        }
    }
}

TEST(BezierTriangle, InterpolatesCorners) {
    const BezierTriangle b = random_triangle(3, 1);
    EXPECT_LT((b.evaluate(1, 0, 0) - b.points()[0]).norm(), 1e-15);
    EXPECT_LT((b.evaluate(0, 1, 0) - b.points()[6]).norm(), 1e-15);
    EXPECT_LT((b.evaluate(0, 0, 1) - b.points()[9]).norm(), 1e-15);
    EXPECT_EQ(b.corner(1), b.points()[6]);
}

TEST(BezierTriangle, DerivativesMatchFiniteDifferences) {
    std::mt19937 rng(5);
    for (int n : {1, 3, 5}) {
        const BezierTriangle b = random_triangle(n, 20 + n);
        for (int s = 0; s < 10; ++s) {
            const Eigen::Vector3d t = random_bary(rng);
            const double h = 1e-6;
            const Eigen::Vector3d du = (b.evaluate(t + Eigen::Vector3d(h, 0, -h)) - b.evaluate(t - Eigen::Vector3d(h, 0, -h))) / (2 * h);
            const Eigen::Vector3d dv = (b.evaluate(t + Eigen::Vector3d(0, h, -h)) - b.evaluate(t - Eigen::Vector3d(0, h, -h))) / (2 * h);
            EXPECT_LT((b.derivative_u(t) - du).norm(), 1e-6);
            EXPECT_LT((b.derivative_v(t) - dv).norm(), 1e-6);
            EXPECT_NEAR(b.normal(t).norm(), 1.0, 1e-12);
            EXPECT_NEAR(b.normal(t).dot(du), 0.0, 1e-6);
        }
    }
}

TEST(BezierTriangle, FlatTriangleNormalIsCounterClockwise) {
    const BezierTriangle b(1, {{1, 0, 0}, {0, 1, 0}, {0, 0, 0}});
    EXPECT_LT((b.normal({0.2, 0.3, 0.5}) - Eigen::Vector3d(0, 0, 1)).norm(), 1e-15);
}

// Acceptance (issue 5): every subpatch evaluated at its own parameters matches
// the parent within 1e-12; at 1e-6 and 1e6 scale too (relative).
TEST(BezierTriangle, SubpatchReproducesParent) {
    std::mt19937 rng(9);
    for (double scale : {1e-6, 1.0, 1e6})
        for (int n : {1, 2, 3, 4, 6, 10}) {
            const BezierTriangle b = random_triangle(n, 30 + n, scale);
            for (int trial = 0; trial < 5; ++trial) {
                const Eigen::Vector3d r = random_bary(rng), s = random_bary(rng), t = random_bary(rng);
                const BezierTriangle sub = b.subpatch(r, s, t);
                EXPECT_TRUE(trimkit::test::is_finite(sub.bounding_box().min()));
                for (int q = 0; q < 10; ++q) {
                    const Eigen::Vector3d p = random_bary(rng);
                    const Eigen::Vector3d parent = b.evaluate(p[0] * r + p[1] * s + p[2] * t);
                    EXPECT_LT((sub.evaluate(p) - parent).norm(), 1e-12 * scale * std::max(1, n))
                        << "n " << n << " scale " << scale;
                }
                // the subpatch lies in its control box
                EXPECT_TRUE(sub.bounding_box().contains(sub.evaluate(random_bary(rng))));
            }
        }
}

TEST(BezierTriangle, SubpatchOfWholeDomainIsIdentity) {
    const BezierTriangle b = random_triangle(4, 2);
    const BezierTriangle same = b.subpatch({1, 0, 0}, {0, 1, 0}, {0, 0, 1});
    for (std::size_t q = 0; q < b.points().size(); ++q) EXPECT_LT((same.points()[q] - b.points()[q]).norm(), 1e-15);
}

TEST(BezierTriangle, RejectsInvalidInput) {
    EXPECT_THROW(BezierTriangle(0, {{0, 0, 0}}), InvalidInput);
    EXPECT_THROW(BezierTriangle(21, std::vector<Eigen::Vector3d>(253)), InvalidInput);
    EXPECT_THROW(BezierTriangle(2, std::vector<Eigen::Vector3d>(5, Eigen::Vector3d::Zero())), InvalidInput);
    std::vector<Eigen::Vector3d> P(3, Eigen::Vector3d::Zero());
    P[1].y() = std::numeric_limits<double>::quiet_NaN();
    try {
        BezierTriangle(1, P);
        FAIL();
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("point[1]"), std::string::npos);
    }
}

TEST(BezierTriangle, DegenerateCornerStillHasNormal) {
    // cubic whose three control points next to corner u = 1 coincide with it
    std::vector<Eigen::Vector3d> P;
    for (int i = 3; i >= 0; --i)
        for (int j = 3 - i; j >= 0; --j) P.emplace_back(j, 3 - i - j, 0.1 * i * j);
    P[1] = P[2] = P[0];
    const BezierTriangle b(3, P);
    EXPECT_NEAR(b.normal({1, 0, 0}).norm(), 1.0, 1e-12);
}

}  // namespace
}  // namespace trimkit::geom
