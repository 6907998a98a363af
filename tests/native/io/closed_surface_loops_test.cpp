// Loops on closed surfaces (io/closed_surface_loops): each loop unwrapped from its
// own start may land whole periods away from the loop that encloses it.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "geom/analytic_curves.h"
#include "geom/analytic_surfaces.h"
#include "geom/face.h"
#include "io/closed_surface_loops.h"

namespace trimkit::io {
namespace {

constexpr double kTwoPi = 2.0 * M_PI;

// The axis-aligned rectangle [u0, u1] x [v0, v1] as four line coedges.
geom::Loop rectangle(double u0, double v0, double u1, double v1) {
    const std::vector<Eigen::Vector2d> corners = {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}};
    geom::Loop loop;
    for (std::size_t k = 0; k < corners.size(); ++k)
        loop.coedges.push_back({geom::line_segment(corners[k], corners[(k + 1) % corners.size()])});
    return loop;
}

double low_u(const geom::Loop& loop) {
    double u = INFINITY;
    for (const geom::Coedge& e : loop.coedges) u = std::min(u, e.curve.evaluate(e.curve.domain().first).x());
    return u;
}

// A hole at u in [7, 7.5] beside an outer loop on [0, 6], period 2pi in u: the hole
// moves by -2pi (its centre 7.25 lands on 0.967, inside [0, 6]); the outer loop stays.
TEST(PlaceLoopsByLargest, HoleAPeriodAwayMovesIntoTheOuterLoopsRange) {
    std::vector<geom::Loop> loops = {rectangle(0, 0, 6, 1), rectangle(7, 0.2, 7.5, 0.4)};
    ASSERT_TRUE(place_loops_by_largest(loops, {kTwoPi, 0.0}));
    EXPECT_NEAR(low_u(loops[0]), 0.0, 1e-12);
    EXPECT_NEAR(low_u(loops[1]), 7.0 - kTwoPi, 1e-12);
}

// The largest loop decides, wherever it is listed; a loop already inside its range
// and a surface closed in neither direction move nothing.
TEST(PlaceLoopsByLargest, LargestLoopAnywhereInTheListIsTheReference) {
    std::vector<geom::Loop> loops = {rectangle(-5.5, 0.2, -5, 0.4), rectangle(0, 0, 6, 1)};
    ASSERT_TRUE(place_loops_by_largest(loops, {kTwoPi, 0.0}));
    EXPECT_NEAR(low_u(loops[0]), -5.5 + kTwoPi, 1e-12);
    EXPECT_NEAR(low_u(loops[1]), 0.0, 1e-12);

    std::vector<geom::Loop> inside = {rectangle(0, 0, 6, 1), rectangle(2, 0.2, 3, 0.4)};
    EXPECT_FALSE(place_loops_by_largest(inside, {kTwoPi, 0.0}));
    std::vector<geom::Loop> open = {rectangle(0, 0, 6, 1), rectangle(7, 0.2, 7.5, 0.4)};
    EXPECT_FALSE(place_loops_by_largest(open, {}));
    EXPECT_NEAR(low_u(open[1]), 7.0, 1e-12);
}

// No whole period puts the centre in range (the outer loop spans 1 of a period of
// 2pi, the hole is 3 away): the loop stays where it is rather than move a period.
TEST(PlaceLoopsByLargest, NoShiftWhenNoWholePeriodLandsInRange) {
    std::vector<geom::Loop> loops = {rectangle(0, 0, 1, 1), rectangle(3.9, 0.2, 4.1, 0.4)};
    EXPECT_FALSE(place_loops_by_largest(loops, {kTwoPi, 0.0}));
    EXPECT_NEAR(low_u(loops[1]), 3.9, 1e-12);
}

double low_v(const geom::Loop& loop) {
    double v = INFINITY;
    for (const geom::Coedge& e : loop.coedges) v = std::min(v, e.curve.evaluate(e.curve.domain().first).y());
    return v;
}

// A fillet's quarter tube unwrapped onto v in [-3pi/2, -pi] on a torus of v in
// [-pi, pi]: one shift of 2pi puts it (and its hole) inside the domain, so the
// surface need not be extended; loops that no shift fits stay.
TEST(ShiftLoopsIntoDomain, WholeFaceMovesByAPeriodWhereOneShiftFits) {
    const geom::NurbsSurface torus = geom::torus_patch(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(),
                                                       Eigen::Vector3d::UnitX(), 8, 2, 0, kTwoPi, -M_PI, M_PI);
    const SurfacePeriods periods{kTwoPi, kTwoPi};
    std::vector<geom::Loop> loops = {rectangle(0, -1.5 * M_PI, kTwoPi, -M_PI), rectangle(1, -4, 2, -3.5)};
    ASSERT_TRUE(shift_loops_into_domain(loops, torus, periods));
    EXPECT_NEAR(low_v(loops[0]), 0.5 * M_PI, 1e-12);
    EXPECT_NEAR(low_v(loops[1]), -4 + kTwoPi, 1e-12);
    EXPECT_NEAR(low_u(loops[0]), 0.0, 1e-12);

    std::vector<geom::Loop> wide = {rectangle(0, -4, 1, 2)};  // 6 of v: no shift fits
    EXPECT_FALSE(shift_loops_into_domain(wide, torus, periods));
    std::vector<geom::Loop> inside = {rectangle(0, 0, 1, 1)};
    EXPECT_FALSE(shift_loops_into_domain(inside, torus, periods));
}

}  // namespace
}  // namespace trimkit::io
