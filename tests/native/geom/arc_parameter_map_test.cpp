#include "geom/arc_parameter_map.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geom/analytic_curves.h"
#include "geom/error.h"

namespace trimkit::geom {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180;

struct Sweep {
    double theta0, theta1;
    int segments;
};

const Sweep kSweeps[] = {{0.3, 0.3 + 10 * kDeg, 1},   {0, kPi / 2, 1},
                         {-1.0, -1.0 + 200 * kDeg, 3}, {0, 2 * kPi, 4},
                         {2.0, 2.0 - 135 * kDeg, 2},   {kPi, -kPi, 4},
                         {5.0, 5.0 + 91 * kDeg, 2}};

TEST(ArcParameterMap, SegmentsAndKnotsSitAtEqualAngles) {
    for (const Sweep& s : kSweeps) {
        ArcParameterMap map(s.theta0, s.theta1);
        ASSERT_EQ(map.segments(), s.segments) << s.theta0 << " -> " << s.theta1;
        const double sigma = s.theta1 > s.theta0 ? 1 : -1;
        EXPECT_EQ(map.knots().front(), sigma * s.theta0);
        EXPECT_EQ(map.knots().back(), sigma * s.theta1);
        for (int i = 0; i <= map.segments(); ++i) {
            const double a = s.theta0 + (s.theta1 - s.theta0) * i / map.segments();
            EXPECT_NEAR(map.knots()[i], sigma * a, 1e-15);
            EXPECT_NEAR(map.to_nurbs(a), sigma * a, 1e-14);
            EXPECT_NEAR(map.to_angle(sigma * a), a, 1e-14);
        }
    }
}

TEST(ArcParameterMap, RoundTripIsExact) {
    for (const Sweep& s : kSweeps) {
        ArcParameterMap map(s.theta0, s.theta1);
        for (int j = 0; j <= 1000; ++j) {
            const double theta = s.theta0 + (s.theta1 - s.theta0) * j / 1000.0;
            EXPECT_NEAR(map.to_angle(map.to_nurbs(theta)), theta, 1e-14);
            const double t = map.knots().front() +
                             (map.knots().back() - map.knots().front()) * j / 1000.0;
            EXPECT_NEAR(map.to_nurbs(map.to_angle(t)), t, 1e-14);
        }
    }
}

TEST(ArcParameterMap, IsMonotoneAndClampsOutside) {
    ArcParameterMap map(0.5, 0.5 + 200 * kDeg);
    double prev = -1e300;
    for (int j = 0; j <= 2000; ++j) {
        const double t = map.to_nurbs(0.5 + 200 * kDeg * j / 2000.0);
        EXPECT_GT(t, prev);
        prev = t;
    }
    EXPECT_EQ(map.to_nurbs(-3.0), 0.5);
    EXPECT_EQ(map.to_nurbs(100.0), map.knots().back());
    EXPECT_EQ(map.to_angle(-3.0), 0.5);
    EXPECT_EQ(map.to_angle(100.0), map.theta1());
}

TEST(ArcParameterMap, DerivativeMatchesFiniteDifferences) {
    for (const Sweep& s : kSweeps) {
        ArcParameterMap map(s.theta0, s.theta1);
        const double h = 1e-6;
        for (int j = 1; j < 100; ++j) {
            const double theta = s.theta0 + (s.theta1 - s.theta0) * j / 100.0;
            const double fd = (map.to_nurbs(theta + h) - map.to_nurbs(theta - h)) / (2 * h);
            // 1e-6: the central difference straddles the jump in d²t/dθ² at knots.
            EXPECT_NEAR(map.nurbs_derivative(theta), fd, 1e-6);
        }
    }
}

TEST(ArcParameterMap, CircularArcEvaluatesAtTheAngle) {
    const Eigen::Vector3d c(1, -2, 0.5);
    const Eigen::Vector3d x = Eigen::Vector3d(1, 1, 0).normalized();
    const Eigen::Vector3d y = Eigen::Vector3d(-1, 1, 1).normalized();  // ⟂ x
    const double r = 2.5;
    for (const Sweep& s : kSweeps) {
        ArcParameterMap map(s.theta0, s.theta1);
        NurbsCurve3d arc = circular_arc(c, x, y, r, s.theta0, s.theta1);
        EXPECT_EQ(arc.domain().first, map.knots().front());
        EXPECT_EQ(arc.domain().second, map.knots().back());
        for (int j = 0; j <= 500; ++j) {
            const double theta = s.theta0 + (s.theta1 - s.theta0) * j / 500.0;
            const Eigen::Vector3d expected = c + r * (std::cos(theta) * x + std::sin(theta) * y);
            EXPECT_LT((arc.evaluate(map.to_nurbs(theta)) - expected).norm(), 1e-12 * r)
                << "theta " << theta << " of arc " << s.theta0 << " -> " << s.theta1;
        }
    }
}

TEST(ArcParameterMap, RejectsEmptyOversizedAndNonFiniteSweeps) {
    EXPECT_THROW(ArcParameterMap(1.0, 1.0), InvalidInput);
    EXPECT_THROW(ArcParameterMap(0.0, 7.0), InvalidInput);
    EXPECT_THROW(ArcParameterMap(0.0, NAN), InvalidInput);
    EXPECT_NO_THROW(ArcParameterMap(-kPi, kPi));
}

}  // namespace
}  // namespace trimkit::geom
