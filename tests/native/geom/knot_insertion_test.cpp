// Tests for geom/knot_insertion.h, the knot insertion ([PT] A5.1) and Bezier
// decomposition ([PT] A5.6) that curves and surfaces share: rows of 1D "points"
// (a scalar spline and its weight) against the B-spline evaluated from its basis
// functions, on knot vectors the curve tests do not reach (unclamped ends, interior
// knots of multiplicity p and p + 1, degree 5).
#include "geom/knot_insertion.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geom/bspline_basis.h"
#include "geom/error.h"
#include "geom/knot_vector.h"
#include "geom/nurbs_surface.h"

namespace trimkit::geom {
namespace {

using Row = std::vector<Eigen::Vector2d>;  // homogeneous (w x, w)

// The rational scalar spline at u by its basis functions (knot_span's closed last span).
double spline_value(const std::vector<double>& U, int p, const Row& P, double u) {
    const int span = knot_span(U, p, u);
    double N[kMaxDegree + 1];
    basis_functions(U, p, span, u, N);
    Eigen::Vector2d h = Eigen::Vector2d::Zero();
    for (int j = 0; j <= p; ++j) h += N[j] * P[span - p + j];
    return h[0] / h[1];
}

// A Bezier piece on [a, b] at u by de Casteljau.
double bezier_value(const Row& points, size_t first, int p, double a, double b, double u) {
    Row q(points.begin() + first, points.begin() + first + p + 1);
    const double t = (u - a) / (b - a);
    for (int r = 1; r <= p; ++r)
        for (int i = 0; i + r <= p; ++i) q[i] = (1 - t) * q[i] + t * q[i + 1];
    return q[0][0] / q[0][1];
}

Row random_row(size_t n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> x(-2, 2), w(0.5, 2);
    Row P(n);
    for (auto& h : P) {
        const double weight = w(rng);
        h = {weight * x(rng), weight};
    }
    return P;
}

struct Case {
    int p;
    std::vector<double> U;
    std::vector<double> breaks;  // the distinct knots of the domain, derived by hand
};

const std::vector<Case>& cases() {
    static const std::vector<Case> all = {
        {3, {0, 0, 0, 0, 0.3, 0.6, 1, 1, 1, 1}, {0, 0.3, 0.6, 1}},
        {2, {0, 1, 2, 3, 4, 5, 6, 7, 8}, {2, 3, 4, 5, 6}},              // unclamped both ends
        {3, {0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 2}, {0, 1, 2}},              // C0 at 1 (multiplicity p)
        {2, {0, 0, 0, 1, 1, 1, 2, 2, 2}, {0, 1, 2}},                    // break at 1 (multiplicity p + 1)
        {5, {-1, -0.5, 0, 0, 0, 0, 0.1, 0.1, 0.7, 2, 2, 2, 2, 2, 3}, {0, 0.1, 0.7, 2}},
    };
    return all;
}

TEST(KnotInsertion, BezierPiecesEqualTheSpline) {
    for (const Case& c : cases()) {
        const Row P = random_row(c.U.size() - c.p - 1, 7);
        const DomainClamp clamp = plan_domain_clamp(c.U, c.p, "test");
        const Row pieces = bezier_pieces(clamp, c.p, P);
        ASSERT_EQ(clamp.breaks, c.breaks);
        ASSERT_EQ(pieces.size(), (c.breaks.size() - 1) * (c.p + 1));
        for (size_t q = 0; q + 1 < c.breaks.size(); ++q) {
            const double a = c.breaks[q], b = c.breaks[q + 1];
            // Inside the span (the spline at a break of multiplicity p + 1 jumps).
            for (int i = 1; i < 20; ++i) {
                const double u = a + (b - a) * i / 20.0;
                EXPECT_NEAR(bezier_value(pieces, q * (c.p + 1), c.p, a, b, u),
                            spline_value(c.U, c.p, P, u), 1e-12)
                    << "degree " << c.p << ", piece " << q << ", u = " << u;
            }
        }
    }
}

TEST(KnotInsertion, PlanCapsMultiplicityAndKeepsTheSpline) {
    for (const Case& c : cases()) {
        const Row P = random_row(c.U.size() - c.p - 1, 3);
        for (double t : {c.breaks.front(), 0.5 * (c.breaks[0] + c.breaks[1]), c.breaks[1]}) {
            const int before = static_cast<int>(std::count(c.U.begin(), c.U.end(), t));
            const KnotInsertion plan = plan_knot_insertion(c.U, c.p, t, 9, "test");
            EXPECT_EQ(plan.r, std::max(0, c.p - before)) << "t = " << t;
            if (plan.r == 0) continue;
            EXPECT_EQ(std::count(plan.knots.begin(), plan.knots.end(), t), c.p);
            const Row Q = insert_knot(plan, P);
            ASSERT_EQ(Q.size(), P.size() + plan.r);
            for (int i = 1; i < 40; ++i) {
                const double u = c.breaks.front() + (c.breaks.back() - c.breaks.front()) * i / 40.0;
                EXPECT_NEAR(spline_value(plan.knots, c.p, Q, u), spline_value(c.U, c.p, P, u), 1e-12);
            }
        }
    }
    const std::vector<double> U{0, 0, 0, 1, 1, 1};
    EXPECT_THROW(plan_knot_insertion(U, 2, 1.5, 1, "test"), InvalidInput);
    EXPECT_THROW(plan_knot_insertion(U, 2, 0.5, -1, "test"), InvalidInput);
}

// The surface's patches come from the same rows: an unclamped, rational surface with
// a C0 knot in v reproduces itself patch by patch.
TEST(KnotInsertion, SurfacePatchesOfUnclampedRationalSurface) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> x(-1, 1), w(0.5, 2);
    const int nu = 6, nv = 5;
    std::vector<Eigen::Vector3d> P;
    std::vector<double> weights;
    for (int i = 0; i < nu * nv; ++i) {
        P.emplace_back(i / nv + x(rng), i % nv + x(rng), x(rng));
        weights.push_back(w(rng));
    }
    const NurbsSurface S(2, 2, {0, 1, 2, 3, 4, 5, 6, 7, 8}, {0, 0, 0, 1, 1, 2, 2, 2}, nu, nv, P, weights);
    const std::vector<NurbsSurface> patches = S.bezier_patches();
    const std::vector<double> bu{2, 3, 4, 5, 6}, bv{0, 1, 2};
    ASSERT_EQ(patches.size(), (bu.size() - 1) * (bv.size() - 1));
    for (size_t a = 0; a + 1 < bu.size(); ++a)
        for (size_t b = 0; b + 1 < bv.size(); ++b) {
            const NurbsSurface& B = patches[a * (bv.size() - 1) + b];
            EXPECT_EQ(B.knots_u(), bezier_knots(2, bu[a], bu[a + 1]));
            EXPECT_EQ(B.knots_v(), bezier_knots(2, bv[b], bv[b + 1]));
            for (int i = 0; i <= 6; ++i)
                for (int j = 0; j <= 6; ++j) {
                    const double u = bu[a] + (bu[a + 1] - bu[a]) * i / 6.0;
                    const double v = bv[b] + (bv[b + 1] - bv[b]) * j / 6.0;
                    EXPECT_NEAR((B.evaluate(u, v) - S.evaluate(u, v)).norm(), 0.0, 1e-12);
                }
        }
}

}  // namespace
}  // namespace trimkit::geom
