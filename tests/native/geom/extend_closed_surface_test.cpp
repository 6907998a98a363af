#include "geom/extend_closed_surface.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geom/analytic_curves.h"
#include "geom/analytic_surfaces.h"
#include "geom/error.h"

namespace trimkit::geom {
namespace {

constexpr double kPi = 3.14159265358979323846;
const Eigen::Vector3d kAxis = Eigen::Vector3d(1, -2, 2).normalized();
const Eigen::Vector3d kRef = Eigen::Vector3d(2, 1, 0).normalized();  // ⟂ kAxis
const Eigen::Vector3d kCenter(3, -1, 0.5);

double wrap(double u, double a, double period) {
    double r = std::fmod(u - a, period);
    return a + (r < 0 ? r + period : r);
}

// Every point of the extension is the original surface at the parameter taken
// modulo the period (the copies are exact), on samples across both seams.
void expect_periodic_copy(const NurbsSurface& s, const NurbsSurface& e, int direction, double scale) {
    const auto [a, b] = direction == 0 ? s.domain_u() : s.domain_v();
    const auto [e0, e1] = direction == 0 ? e.domain_u() : e.domain_v();
    const auto [o0, o1] = direction == 0 ? e.domain_v() : e.domain_u();
    for (int i = 0; i <= 40; ++i)
        for (int j = 0; j <= 4; ++j) {
            const double t = e0 + (e1 - e0) * i / 40, o = o0 + (o1 - o0) * j / 4;
            const double w = wrap(t, a, b - a);
            const Eigen::Vector3d x = direction == 0 ? e.evaluate(t, o) : e.evaluate(o, t);
            const Eigen::Vector3d y = direction == 0 ? s.evaluate(w, o) : s.evaluate(o, w);
            EXPECT_LT((x - y).norm(), 1e-12 * scale) << "t = " << t;
        }
}

TEST(ExtendClosedSurface, CylinderAcrossItsSeamIsTheSameCylinder) {
    const double r = 2.0, h = 3.0;
    const NurbsSurface s = cylinder_patch(kCenter, kAxis, kRef, r, 0, 2 * kPi, 0, h);
    EXPECT_TRUE(is_closed_surface(s, 0, 1e-12));
    EXPECT_FALSE(is_closed_surface(s, 1, 1e-12));
    const NurbsSurface e = extend_closed_surface(s, 0, -kPi / 2, kPi / 2, 1e-12);
    EXPECT_DOUBLE_EQ(e.domain_u().first, -kPi / 2);
    EXPECT_DOUBLE_EQ(e.domain_u().second, kPi / 2);
    EXPECT_EQ(e.domain_v(), s.domain_v());
    expect_periodic_copy(s, e, 0, r);
    // On the cylinder: |S - axis| = r everywhere, including the copied half.
    for (int i = 0; i <= 16; ++i) {
        const Eigen::Vector3d x = e.evaluate(-kPi / 2 + kPi * i / 16, 1.0) - kCenter;
        EXPECT_NEAR((x - x.dot(kAxis) * kAxis).norm(), r, 1e-12);
    }
}

TEST(ExtendClosedSurface, SeveralPeriodsAndTheVDirection) {
    // A torus is closed in both directions: extend v (the tube) over 1.5 turns.
    const NurbsSurface s = torus_patch(kCenter, kAxis, kRef, 3.0, 1.0, 0, 2 * kPi, -kPi, kPi);
    ASSERT_TRUE(is_closed_surface(s, 1, 1e-12));
    const NurbsSurface e = extend_closed_surface(s, 1, -2 * kPi, kPi, 1e-12);
    EXPECT_DOUBLE_EQ(e.domain_v().first, -2 * kPi);
    EXPECT_DOUBLE_EQ(e.domain_v().second, kPi);
    expect_periodic_copy(s, e, 1, 4.0);
    // A range inside the domain is the plain sub-surface.
    const NurbsSurface inside = extend_closed_surface(s, 0, 1.0, 2.0, 1e-12);
    EXPECT_DOUBLE_EQ(inside.domain_u().first, 1.0);
    EXPECT_LT((inside.evaluate(1.5, 0.3) - s.evaluate(1.5, 0.3)).norm(), 1e-12);
}

TEST(ExtendClosedSurface, BoundaryRowWeightsMayDifferByOneFactor) {
    // A square prism as a rational degree-1 surface in u: weights 1..5 along u only
    // reparameterise each side; the last row repeats the first with weight 5x.
    const std::vector<Eigen::Vector3d> ring{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 0}};
    std::vector<Eigen::Vector3d> P;
    std::vector<double> w;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 2; ++j) {
            P.push_back(ring[i] + Eigen::Vector3d(0, 0, 2.0 * j));
            w.push_back(1.0 + i);
        }
    const NurbsSurface s(1, 1, {0, 0, 1, 2, 3, 4, 4}, {0, 0, 1, 1}, 5, 2, P, w);
    ASSERT_TRUE(is_closed_surface(s, 0, 1e-12));
    const NurbsSurface e = extend_closed_surface(s, 0, -1.5, 6.5, 1e-12);
    expect_periodic_copy(s, e, 0, 1.0);
}

TEST(ExtendClosedSurface, RejectsOpenSurfacesAndTooManyPeriods) {
    const NurbsSurface half = cylinder_patch(kCenter, kAxis, kRef, 2.0, 0, kPi, 0, 1);
    EXPECT_FALSE(is_closed_surface(half, 0, 1e-9));
    EXPECT_THROW(extend_closed_surface(half, 0, -1.0, 1.0, 1e-9), InvalidInput);
    // The seam of a sweep of 6.28318 rad (5.3e-6 short of 2π) is 1.1e-5 wide at
    // radius 2: closed within 1e-4, not within 1e-6.
    const NurbsSurface almost = cylinder_patch(kCenter, kAxis, kRef, 2.0, 0, 6.28318, 0, 1);
    EXPECT_TRUE(is_closed_surface(almost, 0, 1e-4));
    EXPECT_FALSE(is_closed_surface(almost, 0, 1e-6));
    const NurbsSurface full = cylinder_patch(kCenter, kAxis, kRef, 2.0, 0, 2 * kPi, 0, 1);
    EXPECT_THROW(extend_closed_surface(full, 0, -10 * kPi, 0.5, 1e-9), InvalidInput);
    EXPECT_THROW(extend_closed_surface(full, 0, 1.0, 1.0, 1e-9), InvalidInput);
}

// Ranges whose period counts do not fit an int (a damaged .brep's p-curves, fuzz_brep):
// refused before any conversion (UBSan flagged the old int cast), near and far alike.
TEST(ExtendClosedSurface, RejectsRangesBeyondIntsAndFarFromTheDomain) {
    const NurbsSurface full = cylinder_patch(kCenter, kAxis, kRef, 2.0, 0, 2 * kPi, 0, 1);
    EXPECT_THROW(extend_closed_surface(full, 0, 0.0, 1.5e17, 1e-9), InvalidInput);
    EXPECT_THROW(extend_closed_surface(full, 0, -1.5e17, 0.5, 1e-9), InvalidInput);
    EXPECT_THROW(extend_closed_surface(full, 0, 1e17, 1e17 + 1.0, 1e-9), InvalidInput);
    const double L = 2 * kPi, away = (kMaxPeriodsAway + 1) * L;
    EXPECT_THROW(extend_closed_surface(full, 0, away + 0.5, away + 1.0, 1e-9), InvalidInput);
    // Within the limits it still extends: a range two periods up.
    const NurbsSurface up = extend_closed_surface(full, 0, 2 * L + 0.5, 2 * L + 1.0, 1e-9);
    EXPECT_NEAR((up.evaluate(2 * L + 0.75, 0.5) - full.evaluate(0.75, 0.5)).norm(), 0.0, 1e-9);
}

}  // namespace
}  // namespace trimkit::geom
