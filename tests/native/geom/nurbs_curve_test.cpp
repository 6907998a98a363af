// Tests for geom/nurbs_curve.h: exact conics, derivatives against finite
// differences, knot-insertion based operations keep the shape, validation.
#include "geom/nurbs_curve.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "geom/error.h"
#include "geom/knot_vector.h"
#include "test_support.h"

namespace trimkit::geom {
namespace {

const double kHalfSqrt2 = std::sqrt(2.0) / 2.0;

// Degree 3, 8 points, non-uniform knots with a double knot at 0.55; weights in
// [0.5, 2] when rational. Points scaled by `scale` and shifted by `offset`.
NurbsCurve3d sample_curve(bool rational, double scale = 1.0,
                          const Eigen::Vector3d& offset = Eigen::Vector3d::Zero()) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coord(-1.0, 1.0), weight(0.5, 2.0);
    std::vector<Eigen::Vector3d> P;
    std::vector<double> w;
    for (int i = 0; i < 8; ++i) {
        P.push_back(offset + scale * Eigen::Vector3d(i + 0.3 * coord(rng), coord(rng), coord(rng)));
        w.push_back(weight(rng));
    }
    std::vector<double> U{0, 0, 0, 0, 0.15, 0.4, 0.55, 0.55, 1, 1, 1, 1};
    return NurbsCurve3d(3, U, P, rational ? w : std::vector<double>{});
}

// Rational quadratic quarter circle of radius r about c in the xy plane.
// [PT] Sec. 7.2: weights 1, sqrt(2)/2, 1 with the middle point at the corner.
NurbsCurve3d quarter_circle(double r, const Eigen::Vector3d& c = Eigen::Vector3d::Zero()) {
    return NurbsCurve3d(2, {0, 0, 0, 1, 1, 1},
                        {c + Eigen::Vector3d(r, 0, 0), c + Eigen::Vector3d(r, r, 0),
                         c + Eigen::Vector3d(0, r, 0)},
                        {1.0, kHalfSqrt2, 1.0});
}

std::vector<double> sample_params(const NurbsCurve3d& c, int count) {
    const auto [a, b] = c.domain();
    std::vector<double> t;
    for (int i = 0; i < count; ++i) t.push_back(a + (b - a) * i / (count - 1.0));
    return t;
}

double max_distance(const NurbsCurve3d& a, const NurbsCurve3d& b, int count = 50) {
    double worst = 0.0;
    for (double t : sample_params(a, count))
        worst = std::max(worst, (a.evaluate(t) - b.evaluate(t)).norm());
    return worst;
}

template <class Curve>
std::string error_message(int degree, std::vector<double> U,
                          std::vector<typename Curve::Point> P, std::vector<double> w = {}) {
    try {
        Curve c(degree, std::move(U), std::move(P), std::move(w));
    } catch (const InvalidInput& e) {
        return e.what();
    }
    return "";
}

TEST(NurbsCurve, QuarterCircleLiesOnCircle) {
    for (double r : {1.0, 1e6, 1e-6}) {
        const Eigen::Vector3d c(3 * r, -r, 0.5 * r);
        const NurbsCurve3d arc = quarter_circle(r, c);
        EXPECT_TRUE(arc.is_rational());
        for (double t : sample_params(arc, 201)) {
            const Eigen::Vector3d P = arc.evaluate(t);
            EXPECT_TRUE(test::is_finite(P));
            EXPECT_NEAR((P - c).norm(), r, 1e-12 * r) << "r = " << r << ", t = " << t;
            EXPECT_NEAR(P.z(), c.z(), 1e-12 * r);
        }
        EXPECT_NEAR((arc.evaluate(0.5) - c - r * Eigen::Vector3d(kHalfSqrt2, kHalfSqrt2, 0)).norm(),
                    0.0, 1e-12 * r);
    }
}

TEST(NurbsCurve, InterpolatesEndPointsAndHasPartitionOfUnity) {
    const NurbsCurve3d c = sample_curve(true);
    // To rounding, not bit for bit: the rational end point is (w P) / w, which clang
    // rounds differently from g++ (the clang sanitizer build of .ci/run).
    EXPECT_NEAR((c.evaluate(0.0) - c.points().front()).norm(), 0.0, 1e-15);
    EXPECT_NEAR((c.evaluate(1.0) - c.points().back()).norm(), 0.0, 1e-15);
    // All points equal => the curve is that point everywhere (partition of unity).
    std::vector<Eigen::Vector3d> same(8, Eigen::Vector3d(1.5, -2, 7));
    const NurbsCurve3d constant(3, c.knots(), same, c.weights());
    for (double t : sample_params(c, 100))
        EXPECT_NEAR((constant.evaluate(t) - same[0]).norm(), 0.0, 1e-14);
}

TEST(NurbsCurve, DerivativesMatchCentralDifferences) {
    for (bool rational : {false, true}) {
        const NurbsCurve3d c = sample_curve(rational);
        const double h = 1e-5;
        for (int i = 1; i < 60; ++i) {
            const double t = i / 60.0 + 0.003;
            const auto D = c.derivatives(t, 2);
            ASSERT_EQ(D.size(), 3u);
            EXPECT_NEAR((D[0] - c.evaluate(t)).norm(), 0.0, 1e-14);
            const Eigen::Vector3d first = (c.evaluate(t + h) - c.evaluate(t - h)) / (2 * h);
            const Eigen::Vector3d second =
                (c.derivatives(t + h, 1)[1] - c.derivatives(t - h, 1)[1]) / (2 * h);
            EXPECT_NEAR((D[1] - first).norm(), 0.0, 1e-6 * std::max(1.0, D[1].norm()))
                << "rational " << rational << ", t = " << t;
            // The double knot at 0.55 makes C'' jump there: skip that neighbourhood.
            if (std::abs(t - 0.55) > 2 * h) {
                EXPECT_NEAR((D[2] - second).norm(), 0.0, 1e-5 * std::max(1.0, D[2].norm()))
                    << "rational " << rational << ", t = " << t;
            }
        }
    }
}

TEST(NurbsCurve, SecondDerivativeMatchesSecondDifference) {
    const NurbsCurve3d c = sample_curve(true);
    const double h = 1e-4;
    for (double t : {0.05, 0.3, 0.47, 0.7, 0.93}) {
        const Eigen::Vector3d fd =
            (c.evaluate(t + h) - 2 * c.evaluate(t) + c.evaluate(t - h)) / (h * h);
        const Eigen::Vector3d exact = c.derivatives(t, 2)[2];
        EXPECT_NEAR((exact - fd).norm(), 0.0, 1e-4 * std::max(1.0, exact.norm()));
    }
}

TEST(NurbsCurve, HigherOrderDerivatives) {
    // Non-rational cubic: 4th derivative is zero; rational: 3rd matches differences.
    const NurbsCurve3d poly = sample_curve(false);
    const auto D = poly.derivatives(0.3, 4);
    ASSERT_EQ(D.size(), 5u);
    EXPECT_EQ(D[4], Eigen::Vector3d::Zero());
    const NurbsCurve3d rat = sample_curve(true);
    const double h = 1e-5;
    for (double t : {0.1, 0.3, 0.8}) {
        const Eigen::Vector3d fd = (rat.derivatives(t + h, 2)[2] - rat.derivatives(t - h, 2)[2]) / (2 * h);
        const Eigen::Vector3d exact = rat.derivatives(t, 3)[3];
        EXPECT_NEAR((exact - fd).norm(), 0.0, 1e-5 * std::max(1.0, exact.norm()));
    }
    EXPECT_THROW(rat.derivatives(0.5, -1), InvalidInput);
}

TEST(NurbsCurve, QuarterCircleTangentIsPerpendicularToRadius) {
    const NurbsCurve3d arc = quarter_circle(2.0);
    for (double t : sample_params(arc, 33)) {
        const auto D = arc.derivatives(t, 2);
        EXPECT_NEAR(D[0].dot(D[1]), 0.0, 1e-12 * D[1].norm());
        // |C|^2 = r^2 => C.C'' + C'.C' = 0.
        EXPECT_NEAR(D[0].dot(D[2]) + D[1].dot(D[1]), 0.0, 1e-11 * D[1].squaredNorm());
    }
}

TEST(NurbsCurve, KnotInsertionKeepsShape) {
    for (bool rational : {false, true}) {
        const NurbsCurve3d c = sample_curve(rational);
        for (double t : {0.0, 0.1, 0.15, 0.55, 0.77, 1.0}) {
            for (int times : {1, 2, 3, 5}) {
                const NurbsCurve3d d = c.insert_knot(t, times);
                EXPECT_LT(max_distance(c, d), 1e-12) << "t = " << t << ", times " << times;
                // Multiplicity is capped at p; the clamped ends are already p + 1.
                const int before = static_cast<int>(std::count(c.knots().begin(), c.knots().end(), t));
                const int expected = std::max(0, std::min(times, 3 - before));
                EXPECT_EQ(d.knots().size(), c.knots().size() + expected) << t << " " << times;
                EXPECT_EQ(d.points().size(), c.points().size() + expected);
                EXPECT_NO_THROW(NurbsCurve3d(d.degree(), d.knots(), d.points(), d.weights()));
            }
        }
    }
    EXPECT_THROW(sample_curve(false).insert_knot(1.5), InvalidInput);
}

TEST(NurbsCurve, KnotInsertionInUnclampedCurve) {
    std::vector<Eigen::Vector3d> P;
    for (int i = 0; i < 6; ++i) P.emplace_back(i, std::sin(i), std::cos(2 * i));
    const NurbsCurve3d c(2, {0, 1, 2, 3, 4, 5, 6, 7, 8}, P, {1, 2, 0.5, 1, 3, 1});
    for (double t : {2.0, 2.5, 4.0, 6.0}) {
        const NurbsCurve3d d = c.insert_knot(t, 2);
        EXPECT_LT(max_distance(c, d), 1e-12) << "t = " << t;
    }
}

TEST(NurbsCurve, NearDuplicateKnotIsSnapped) {
    const NurbsCurve3d c = sample_curve(false);
    const NurbsCurve3d d = c.insert_knot(0.4 + 1e-13);
    EXPECT_EQ(std::count(d.knots().begin(), d.knots().end(), 0.4), 2);
}

TEST(NurbsCurve, SubCurveReproducesPiece) {
    for (bool rational : {false, true}) {
        const NurbsCurve3d c = sample_curve(rational);
        for (auto [a, b] : {std::pair{0.0, 1.0}, {0.2, 0.7}, {0.15, 0.55}, {0.6, 0.61}, {0.0, 0.3}}) {
            const NurbsCurve3d s = c.sub_curve(a, b);
            EXPECT_EQ(s.domain().first, a);
            EXPECT_EQ(s.domain().second, b);
            for (int i = 0; i <= 50; ++i) {
                const double t = a + (b - a) * i / 50.0;
                EXPECT_NEAR((s.evaluate(t) - c.evaluate(t)).norm(), 0.0, 1e-12);
            }
            // Clamped: the ends interpolate the first and last control points.
            EXPECT_NEAR((s.points().front() - c.evaluate(a)).norm(), 0.0, 1e-12);
            EXPECT_NEAR((s.points().back() - c.evaluate(b)).norm(), 0.0, 1e-12);
        }
    }
    EXPECT_THROW(sample_curve(false).sub_curve(0.5, 0.2), InvalidInput);
    EXPECT_THROW(sample_curve(false).sub_curve(-0.5, 0.2), InvalidInput);
}

TEST(NurbsCurve, BezierSegmentsReproduceCurve) {
    for (bool rational : {false, true}) {
        const NurbsCurve3d c = sample_curve(rational);
        const auto segments = c.bezier_segments();
        const std::vector<double> breaks{0, 0.15, 0.4, 0.55, 1};
        ASSERT_EQ(segments.size(), breaks.size() - 1);
        for (size_t k = 0; k < segments.size(); ++k) {
            const NurbsCurve3d& s = segments[k];
            EXPECT_EQ(s.points().size(), 4u);
            EXPECT_EQ(s.knots(), bezier_knots(3, breaks[k], breaks[k + 1]));
            for (int i = 0; i <= 20; ++i) {
                const double t = breaks[k] + (breaks[k + 1] - breaks[k]) * i / 20.0;
                EXPECT_NEAR((s.evaluate(t) - c.evaluate(t)).norm(), 0.0, 1e-12);
            }
        }
    }
}

TEST(NurbsCurve, ReversedAndReparameterized) {
    const NurbsCurve3d c = sample_curve(true);
    const NurbsCurve3d r = c.reversed();
    EXPECT_EQ(r.domain(), c.domain());
    for (double t : sample_params(c, 50))
        EXPECT_NEAR((r.evaluate(1.0 - t) - c.evaluate(t)).norm(), 0.0, 1e-12);
    const NurbsCurve3d q = c.reparameterized(2.0, 7.0);
    EXPECT_EQ(q.domain(), std::make_pair(2.0, 7.0));
    for (double t : sample_params(c, 50))
        EXPECT_NEAR((q.evaluate(2.0 + 5.0 * t) - c.evaluate(t)).norm(), 0.0, 1e-12);
    EXPECT_THROW(c.reparameterized(1.0, 1.0), InvalidInput);
    // Reversing twice gives back the knots (to rounding) and the points.
    ASSERT_EQ(r.reversed().knots().size(), c.knots().size());
    for (size_t i = 0; i < c.knots().size(); ++i)
        EXPECT_NEAR(r.reversed().knots()[i], c.knots()[i], 1e-15);
    EXPECT_EQ(r.reversed().points(), c.points());
    EXPECT_LT(max_distance(r.reversed(), c), 1e-15);
}

TEST(NurbsCurve, ControlBoxContainsCurve) {
    const NurbsCurve3d c = sample_curve(true);
    // Grown by rounding (1e-15 of its diagonal): the end points are control points up to
    // the last bit, (w P) / w (clang's build rounds them outside by an ulp).
    auto box = c.control_box();
    const double roundoff = 1e-15 * box.diagonal().norm();
    box.min().array() -= roundoff;
    box.max().array() += roundoff;
    for (double t : sample_params(c, 200)) EXPECT_TRUE(box.contains(c.evaluate(t)));
}

TEST(NurbsCurve, TransformedCommutesWithEvaluation) {
    const NurbsCurve3d c = sample_curve(true);
    Eigen::Affine3d T = Eigen::Translation3d(1, -2, 3) *
                        Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()) *
                        Eigen::Scaling(2.0, 0.5, 1.5);
    const NurbsCurve3d d = c.transformed(T);
    for (double t : sample_params(c, 50))
        EXPECT_NEAR((d.evaluate(t) - T * c.evaluate(t)).norm(), 0.0, 1e-12);

    const NurbsCurve2d flat(2, {0, 0, 0, 1, 1, 1}, {{1, 0}, {1, 1}, {0, 1}}, {1, kHalfSqrt2, 1});
    Eigen::Affine2d T2 = Eigen::Translation2d(4, 5) * Eigen::Rotation2Dd(0.3);
    const NurbsCurve2d moved = flat.transformed(T2);
    for (int i = 0; i <= 50; ++i) {
        const double t = i / 50.0;
        EXPECT_NEAR((moved.evaluate(t) - Eigen::Vector2d(4, 5)).norm(), 1.0, 1e-12);
        EXPECT_NEAR((moved.evaluate(t) - T2 * flat.evaluate(t)).norm(), 0.0, 1e-12);
    }
}

TEST(NurbsCurve, HugeAndTinyScales) {
    const NurbsCurve3d unit = sample_curve(true);
    for (double scale : {1e6, 1e-6}) {
        const Eigen::Vector3d offset = scale * Eigen::Vector3d(10, -20, 5);
        const NurbsCurve3d c = sample_curve(true, scale, offset);
        for (double t : sample_params(c, 50)) {
            const auto D = c.derivatives(t, 2);
            const auto E = unit.derivatives(t, 2);
            EXPECT_TRUE(test::is_finite(D[2]));
            EXPECT_NEAR((D[0] - (offset + scale * E[0])).norm(), 0.0, 1e-12 * scale * 30);
            EXPECT_NEAR((D[1] - scale * E[1]).norm(), 0.0, 1e-11 * scale * E[1].norm());
            EXPECT_NEAR((D[2] - scale * E[2]).norm(), 0.0, 1e-10 * scale * std::max(1.0, E[2].norm()));
        }
        EXPECT_LT(max_distance(c, c.insert_knot(0.33, 2)), 1e-12 * scale * 30);
    }
}

TEST(NurbsCurve, ValidationErrorsNameTheProblem) {
    using P3 = Eigen::Vector3d;
    const std::vector<P3> pts{P3(0, 0, 0), P3(1, 0, 0), P3(1, 1, 0), P3(0, 1, 0)};
    const std::vector<double> U{0, 0, 0, 0.5, 1, 1, 1};

    std::string m = error_message<NurbsCurve3d>(2, {0, 0, 0, 0.6, 0.5, 1, 1}, pts);
    EXPECT_EQ(m, "NurbsCurve: knot[4] = 0.5 < knot[3] = 0.6; knots must be non-decreasing");

    std::vector<P3> bad = pts;
    bad[2].y() = std::numeric_limits<double>::quiet_NaN();
    m = error_message<NurbsCurve3d>(2, U, bad);
    EXPECT_NE(m.find("point[2]"), std::string::npos) << m;
    EXPECT_NE(m.find("finite"), std::string::npos) << m;

    m = error_message<NurbsCurve3d>(2, U, pts, {1, -0.5, 1, 1});
    EXPECT_NE(m.find("weight[1] = -0.5"), std::string::npos) << m;
    EXPECT_NE(error_message<NurbsCurve3d>(2, U, pts, {1, 0, 1, 1}).find("weight"), std::string::npos);
    EXPECT_NE(error_message<NurbsCurve3d>(2, U, pts, {1, 1, 1}).find("weights"), std::string::npos);
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_NE(error_message<NurbsCurve3d>(2, U, pts, {1, inf, 1, 1}).find("weight"), std::string::npos);

    m = error_message<NurbsCurve3d>(10000, U, pts);
    EXPECT_NE(m.find("degree"), std::string::npos) << m;
    EXPECT_NE(m.find("10000"), std::string::npos) << m;
    EXPECT_NE(error_message<NurbsCurve3d>(0, U, pts).find("degree"), std::string::npos);
    EXPECT_NE(error_message<NurbsCurve3d>(2, {0, 0, 0, 1, 1, 1}, pts).find("knots"),
              std::string::npos);

    const std::vector<Eigen::Vector2d> flat{{0, 0}, {1, 0}, {1, 1}};
    m = error_message<NurbsCurve2d>(2, {0, 0, 0, 1, 1, 1}, flat, {1, 1, -2});
    EXPECT_NE(m.find("weight[2] = -2"), std::string::npos) << m;
}

}  // namespace
}  // namespace trimkit::geom
