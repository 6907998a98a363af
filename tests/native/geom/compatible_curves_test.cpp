#include "geom/compatible_curves.h"

#include <gtest/gtest.h>

#include "geom/analytic_curves.h"
#include "geom/error.h"

namespace trimkit::geom {
namespace {

TEST(CompatibleCurves, SameDegreeAndKnotsSameShapes) {
    const NurbsCurve3d arc = circular_arc(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(),
                                          Eigen::Vector3d::UnitY(), 1.0, 0.0, 4.0);
    std::vector<Eigen::Vector3d> P{{0, 0, 1}, {1, 2, 1}, {2, -1, 1}, {3, 0, 2}, {4, 1, 1}};
    const NurbsCurve3d cubic(3, {5, 5, 5, 5, 6.5, 8, 8, 8, 8}, P);
    const auto [a, b] = make_compatible(arc, cubic);
    EXPECT_EQ(a.degree(), 3);
    EXPECT_EQ(b.degree(), 3);
    EXPECT_EQ(a.knots(), b.knots());
    EXPECT_EQ(a.domain(), std::make_pair(0.0, 1.0));
    EXPECT_TRUE(a.is_rational());
    EXPECT_FALSE(b.is_rational());
    for (int j = 0; j <= 200; ++j) {
        const double s = j / 200.0;
        EXPECT_LT((a.evaluate(s) - arc.evaluate(4.0 * s)).norm(), 1e-12);
        EXPECT_LT((b.evaluate(s) - cubic.evaluate(5 + 3 * s)).norm(), 1e-12);
    }
}

TEST(CompatibleCurves, CommonWeightsKeepShapesAndParameters) {
    const NurbsCurve3d arc = circular_arc(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(),
                                          Eigen::Vector3d::UnitY(), 1.0, 0.0, 4.0);
    std::vector<Eigen::Vector3d> P{{0, 0, 1}, {1, 2, 1}, {2, -1, 1}, {3, 0, 2}, {4, 1, 1}};
    const NurbsCurve3d cubic(3, {0, 0, 0, 0, 0.5, 1, 1, 1, 1}, P, {1, 2, 0.5, 1, 1});
    const auto [a0, b0] = make_compatible(arc, cubic);
    const auto [a, b] = make_compatible_weights(a0, b0);
    EXPECT_EQ(a.degree(), 6);
    EXPECT_EQ(a.knots(), b.knots());
    EXPECT_EQ(a.weights(), b.weights());
    for (int j = 0; j <= 200; ++j) {
        const double s = j / 200.0;
        EXPECT_LT((a.evaluate(s) - a0.evaluate(s)).norm(), 1e-12);
        EXPECT_LT((b.evaluate(s) - b0.evaluate(s)).norm(), 1e-12);
    }
    // Equal weights: nothing to do.
    const auto [c, d] = make_compatible_weights(b0, b0);
    EXPECT_EQ(c.degree(), 3);
    EXPECT_THROW(make_compatible_weights(arc, cubic), InvalidInput);
}

}  // namespace
}  // namespace trimkit::geom
