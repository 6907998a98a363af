// Tests for geom/bspline_basis.h: spans, partition of unity, derivatives.
#include "geom/bspline_basis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <vector>

namespace trimkit::geom {
namespace {

struct Case {
    int p;
    std::vector<double> U;
};

// Clamped, unclamped, repeated interior knots, non-zero-based domains.
std::vector<Case> cases() {
    return {
        {1, {0, 0, 0.3, 0.7, 1, 1}},
        {2, {0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5}},  // [PT] Ex. 2.3
        {3, {0, 0, 0, 0, 0.2, 0.2, 0.5, 0.9, 1, 1, 1, 1}},
        {2, {-3, -2, -1, 0, 1, 2, 3, 4}},  // unclamped uniform
        {4, {10, 10, 10, 10, 10, 10.5, 10.5, 10.5, 10.5, 12, 12, 12, 12, 12}},
        {5, {0, 0, 0, 0, 0, 0, 1e-6, 2e-6, 3e-6, 3e-6, 3e-6, 3e-6, 3e-6, 3e-6}},
    };
}

double domain_start(const Case& c) { return c.U[c.p]; }
double domain_end(const Case& c) { return c.U[c.U.size() - c.p - 1]; }

TEST(BsplineBasis, KnotSpanBracketsParameter) {
    for (const Case& c : cases()) {
        const int n = static_cast<int>(c.U.size()) - c.p - 2;
        const double a = domain_start(c), b = domain_end(c);
        for (int k = 0; k < 500; ++k) {
            const double u = a + (b - a) * k / 500.0;
            const int span = knot_span(c.U, c.p, u);
            ASSERT_GE(span, c.p);
            ASSERT_LE(span, n);
            EXPECT_LE(c.U[span], u);
            EXPECT_LT(u, c.U[span + 1]);
        }
        // The closed right end belongs to the last non-empty span.
        const int last = knot_span(c.U, c.p, b);
        EXPECT_LT(c.U[last], c.U[last + 1]);
        EXPECT_EQ(c.U[last + 1], b);
        // Outside the domain: clamped.
        EXPECT_EQ(knot_span(c.U, c.p, b + 1.0), last);
        EXPECT_EQ(knot_span(c.U, c.p, a - 1.0), knot_span(c.U, c.p, a));
    }
}

TEST(BsplineBasis, KnotSpanOfBookExample) {
    // [PT] Ex. 2.3: u = 5/2 lies in span 4 of U = {0,0,0,1,2,3,4,4,5,5,5}.
    EXPECT_EQ(knot_span(cases()[1].U, 2, 2.5), 4);
    EXPECT_EQ(knot_span(cases()[1].U, 2, 4.0), 7);  // 4 has multiplicity 2: span 7
    EXPECT_EQ(knot_span(cases()[1].U, 2, 5.0), 7);
}

TEST(BsplineBasis, BookExampleValues) {
    // [PT] Ex. 2.3: N_{2,2}(5/2) = 1/8, N_{3,2}(5/2) = 6/8, N_{4,2}(5/2) = 1/8.
    double N[3];
    basis_functions(cases()[1].U, 2, 4, 2.5, N);
    EXPECT_NEAR(N[0], 0.125, 1e-15);
    EXPECT_NEAR(N[1], 0.75, 1e-15);
    EXPECT_NEAR(N[2], 0.125, 1e-15);
    // Their derivatives: -1/2, 0, 1/2.
    const auto ders = basis_function_derivatives(cases()[1].U, 2, 4, 2.5, 1);
    EXPECT_NEAR(ders[1][0], -0.5, 1e-15);
    EXPECT_NEAR(ders[1][1], 0.0, 1e-15);
    EXPECT_NEAR(ders[1][2], 0.5, 1e-15);
}

TEST(BsplineBasis, PartitionOfUnityAndNonNegativity) {
    for (const Case& c : cases()) {
        const double a = domain_start(c), b = domain_end(c);
        for (int k = 0; k <= 1000; ++k) {
            const double u = a + (b - a) * k / 1000.0;
            const int span = knot_span(c.U, c.p, u);
            double N[kMaxDegree + 1];
            basis_functions(c.U, c.p, span, u, N);
            double sum = 0.0;
            for (int j = 0; j <= c.p; ++j) {
                EXPECT_GE(N[j], 0.0) << "p = " << c.p << ", u = " << u;
                sum += N[j];
            }
            EXPECT_NEAR(sum, 1.0, 1e-14) << "p = " << c.p << ", u = " << u;
        }
    }
}

TEST(BsplineBasis, DerivativeRowZeroEqualsBasisAndHigherRowsSumToZero) {
    for (const Case& c : cases()) {
        const double a = domain_start(c), b = domain_end(c);
        for (int k = 0; k <= 200; ++k) {
            const double u = a + (b - a) * k / 200.0;
            const int span = knot_span(c.U, c.p, u);
            double N[kMaxDegree + 1];
            basis_functions(c.U, c.p, span, u, N);
            const auto ders = basis_function_derivatives(c.U, c.p, span, u, c.p + 2);
            ASSERT_EQ(ders.size(), static_cast<size_t>(c.p + 3));
            for (int j = 0; j <= c.p; ++j) EXPECT_NEAR(ders[0][j], N[j], 1e-15);
            for (int order = 1; order <= c.p; ++order) {
                const double sum = std::accumulate(ders[order].begin(), ders[order].end(), 0.0);
                double scale = 0.0;
                for (double d : ders[order]) scale = std::max(scale, std::abs(d));
                EXPECT_NEAR(sum, 0.0, 1e-12 * std::max(1.0, scale)) << "order " << order;
            }
            // Above the degree every derivative vanishes.
            for (int order = c.p + 1; order <= c.p + 2; ++order)
                for (double d : ders[order]) EXPECT_EQ(d, 0.0);
        }
    }
}

TEST(BsplineBasis, DerivativesMatchCentralDifferences) {
    for (const Case& c : cases()) {
        const double a = domain_start(c), b = domain_end(c);
        const double h = 1e-6 * (b - a);
        for (int k = 1; k < 97; ++k) {
            const double u = a + (b - a) * (k + 0.37) / 98.0;
            const int span = knot_span(c.U, c.p, u);
            // Stay inside one span so the finite difference sees one polynomial.
            if (u - 2 * h < c.U[span] || u + 2 * h >= c.U[span + 1]) continue;
            const auto ders = basis_function_derivatives(c.U, c.p, span, u, 2);
            double Np[kMaxDegree + 1], Nm[kMaxDegree + 1];
            basis_functions(c.U, c.p, span, u + h, Np);
            basis_functions(c.U, c.p, span, u - h, Nm);
            const auto dp = basis_function_derivatives(c.U, c.p, span, u + h, 1);
            const auto dm = basis_function_derivatives(c.U, c.p, span, u - h, 1);
            for (int j = 0; j <= c.p; ++j) {
                const double first = (Np[j] - Nm[j]) / (2 * h);
                const double second = (dp[1][j] - dm[1][j]) / (2 * h);
                const double s1 = 1.0 / (b - a), s2 = s1 * s1;
                EXPECT_NEAR(ders[1][j], first, 1e-6 * std::max(s1, std::abs(first)));
                if (c.p >= 2) {
                    EXPECT_NEAR(ders[2][j], second, 1e-5 * std::max(s2, std::abs(second)));
                }
            }
        }
    }
}

TEST(BsplineBasis, FlatAndNestedDerivativeFormsAgree) {
    const Case c = cases()[2];
    const int span = knot_span(c.U, c.p, 0.6);
    const auto nested = basis_function_derivatives(c.U, c.p, span, 0.6, 3);
    std::vector<double> flat(4 * (c.p + 1));
    basis_function_derivatives(c.U, c.p, span, 0.6, 3, flat.data());
    for (int k = 0; k <= 3; ++k)
        for (int j = 0; j <= c.p; ++j) EXPECT_EQ(nested[k][j], flat[k * (c.p + 1) + j]);
}

TEST(BsplineBasis, MaximumDegreeIsEvaluable) {
    // Bernstein basis of degree kMaxDegree: still a partition of unity.
    std::vector<double> U(2 * (kMaxDegree + 1), 0.0);
    for (int i = kMaxDegree + 1; i < 2 * (kMaxDegree + 1); ++i) U[i] = 1.0;
    for (double u : {0.0, 0.25, 0.5, 0.9, 1.0}) {
        double N[kMaxDegree + 1];
        basis_functions(U, kMaxDegree, knot_span(U, kMaxDegree, u), u, N);
        double sum = 0.0;
        for (double x : N) sum += x;
        EXPECT_NEAR(sum, 1.0, 1e-13);
    }
}

}  // namespace
}  // namespace trimkit::geom
