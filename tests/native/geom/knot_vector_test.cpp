// Tests for geom/knot_vector.h: validation messages and knot queries.
#include "geom/knot_vector.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "geom/bspline_basis.h"
#include "geom/error.h"

namespace trimkit::geom {
namespace {

// The InvalidInput message thrown by validate_knot_vector, or "" if none.
std::string validation_message(const std::vector<double>& U, int p, int points) {
    try {
        validate_knot_vector(U, p, points, "NurbsCurve");
    } catch (const InvalidInput& e) {
        return e.what();
    }
    return "";
}

TEST(KnotVector, AcceptsClampedUnclampedAndDiscontinuousVectors) {
    EXPECT_EQ(validation_message({0, 0, 0, 1, 1, 1}, 2, 3), "");
    EXPECT_EQ(validation_message({0, 1, 2, 3, 4, 5, 6}, 2, 4), "");
    EXPECT_EQ(validation_message({0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1}, 2, 6), "");
}

TEST(KnotVector, DecreasingKnotNamesBothValues) {
    EXPECT_EQ(validation_message({0, 0, 0, 0.1, 0.3, 0.2, 1, 1, 1}, 2, 6),
              "NurbsCurve: knot[5] = 0.2 < knot[4] = 0.3; knots must be non-decreasing");
}

TEST(KnotVector, WrongCountNamesExpectedCount) {
    EXPECT_EQ(validation_message({0, 0, 0, 1, 1, 1, 1}, 2, 6),
              "NurbsCurve: 7 knots, expected 9 (degree 2, 6 control points)");
}

TEST(KnotVector, RejectsNonFiniteKnot) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::string message = validation_message({0, 0, 0, nan, 1, 1, 1}, 2, 4);
    EXPECT_NE(message.find("knot[3] = nan"), std::string::npos) << message;
    EXPECT_NE(message.find("finite"), std::string::npos) << message;
    const double inf = std::numeric_limits<double>::infinity();
    EXPECT_NE(validation_message({0, 0, 0, 1, 1, inf}, 2, 3), "");
}

TEST(KnotVector, RejectsMultiplicityAboveDegreePlusOne) {
    const std::string message = validation_message({0, 0, 0, 0.5, 0.5, 0.5, 0.5, 1, 1, 1}, 2, 7);
    EXPECT_NE(message.find("multiplicity 4"), std::string::npos) << message;
}

TEST(KnotVector, RejectsEmptyDomain) {
    // Degree 1, two points: the domain [U[1], U[2]] = [1, 1] is empty.
    const std::string message = validation_message({0, 1, 1, 2}, 1, 2);
    EXPECT_NE(message.find("empty domain"), std::string::npos) << message;
}

TEST(KnotVector, RejectsBadDegreeAndTooFewPoints) {
    EXPECT_NE(validation_message({0, 1}, 0, 1).find("degree 0"), std::string::npos);
    // Degree 10000 is rejected before anything is sized by it.
    EXPECT_NE(validation_message({0, 0, 1, 1}, 10000, 2).find("degree 10000"), std::string::npos);
    EXPECT_NE(validation_message({0, 0, 0, 1, 1, 1}, 3, 2).find("control points"),
              std::string::npos);
}

TEST(KnotVector, DistinctKnotsAndMultiplicity) {
    const std::vector<double> U{0, 0, 0, 0.25, 0.5, 0.5, 0.75, 1, 1, 1};
    EXPECT_EQ(distinct_knots(U, 2), (std::vector<double>{0, 0.25, 0.5, 0.75, 1}));
    EXPECT_EQ(knot_multiplicity(U, 0.0), 3);
    EXPECT_EQ(knot_multiplicity(U, 0.5), 2);
    EXPECT_EQ(knot_multiplicity(U, 0.5 + 1e-13), 2);  // within kKnotTolerance
    EXPECT_EQ(knot_multiplicity(U, 0.6), 0);
    // Unclamped: only the domain [U[p], U[n+1]] counts.
    EXPECT_EQ(distinct_knots({0, 1, 2, 3, 4, 5, 6}, 2), (std::vector<double>{2, 3, 4}));
}

TEST(KnotVector, UniformClampedAndBezierKnots) {
    EXPECT_EQ(uniform_clamped_knots(5, 2), (std::vector<double>{0, 0, 0, 1.0 / 3, 2.0 / 3, 1, 1, 1}));
    EXPECT_EQ(uniform_clamped_knots(3, 2, -1, 4), (std::vector<double>{-1, -1, -1, 4, 4, 4}));
    EXPECT_EQ(bezier_knots(3, 2, 5), (std::vector<double>{2, 2, 2, 2, 5, 5, 5, 5}));
    EXPECT_NO_THROW(validate_knot_vector(uniform_clamped_knots(17, 4, 3, 9), 4, 17, "test"));
    EXPECT_THROW(uniform_clamped_knots(2, 3), InvalidInput);
    EXPECT_THROW(uniform_clamped_knots(5, 2, 1, 1), InvalidInput);
}

TEST(KnotVector, FormatValueRoundTrips) {
    EXPECT_EQ(format_value(0.2), "0.2");
    EXPECT_EQ(format_value(-0.5), "-0.5");
    const double x = 0.5 + 1e-12;
    EXPECT_EQ(std::stod(format_value(x)), x);
}

}  // namespace
}  // namespace trimkit::geom
