#include "geom/degree_elevation.h"

#include <gtest/gtest.h>

#include "geom/analytic_curves.h"
#include "geom/error.h"
#include "geom/bspline_basis.h"
#include "geom/knot_vector.h"

namespace trimkit::geom {
namespace {

template <int Dim>
double max_distance(const NurbsCurve<Dim>& a, const NurbsCurve<Dim>& b) {
    const auto [lo, hi] = a.domain();
    double worst = 0;
    for (int j = 0; j <= 500; ++j) {
        const double t = lo + (hi - lo) * j / 500.0;
        worst = std::max(worst, (a.evaluate(t) - b.evaluate(t)).norm());
    }
    return worst;
}

NurbsCurve3d cubic_with_double_knot() {
    std::vector<Eigen::Vector3d> P{{0, 0, 0}, {1, 2, 0}, {2, -1, 1}, {3, 0, 2},
                                   {4, 3, 0}, {5, 1, -1}, {6, 0, 0}};
    return NurbsCurve3d(3, {0, 0, 0, 0, 0.3, 0.6, 0.6, 1, 1, 1, 1}, P,
                        {1, 0.5, 2, 1, 1.5, 0.8, 1});
}

TEST(DegreeElevation, LeavesTheCurveUnchanged) {
    const NurbsCurve3d arc = circular_arc(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d::UnitX(),
                                          Eigen::Vector3d::UnitY(), 2.0, 0.0, 5.0);
    const NurbsCurve3d cubic = cubic_with_double_knot();
    const NurbsCurve3d line = line_segment(Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1, 2, 3), 2, 4);
    for (const NurbsCurve3d& c : {arc, cubic, line}) {
        for (int t : {1, 2, 3}) {
            const NurbsCurve3d e = elevate_degree(c, t);
            EXPECT_EQ(e.degree(), c.degree() + t);
            EXPECT_EQ(e.domain(), c.domain());
            EXPECT_EQ(e.is_rational(), c.is_rational());
            EXPECT_LT(max_distance(c, e), 1e-12 * (1 + c.control_box().diagonal().norm()));
        }
    }
}

TEST(DegreeElevation, RaisesEveryKnotMultiplicityByT) {
    const NurbsCurve3d c = cubic_with_double_knot();
    const NurbsCurve3d e = elevate_degree(c, 2);
    EXPECT_EQ(knot_multiplicity(e.knots(), 0.0), 6);
    EXPECT_EQ(knot_multiplicity(e.knots(), 0.3), 3);
    EXPECT_EQ(knot_multiplicity(e.knots(), 0.6), 4);
    EXPECT_EQ(knot_multiplicity(e.knots(), 1.0), 6);
    EXPECT_EQ(e.points().size(), e.knots().size() - 6);
}

TEST(DegreeElevation, ClampsUnclampedCurvesAndWorksIn2d) {
    std::vector<Eigen::Vector2d> P{{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}};
    const NurbsCurve2d c(2, {0, 1, 2, 3, 4, 5, 6, 7}, P);
    const NurbsCurve2d e = elevate_degree(c, 1);
    EXPECT_EQ(e.domain(), c.domain());
    EXPECT_LT(max_distance(c, e), 1e-13);
    EXPECT_THROW(elevate_degree(c, -1), InvalidInput);
    EXPECT_THROW(elevate_degree(c, kMaxDegree), InvalidInput);
}

}  // namespace
}  // namespace trimkit::geom
