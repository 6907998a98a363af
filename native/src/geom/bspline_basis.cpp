// B-spline basis functions. [PT] Chapter 2, Algorithms A2.1 - A2.3.
// Scratch space lives on the stack (sized by kMaxDegree) so evaluation does not
// allocate.
#include "geom/bspline_basis.h"

#include <algorithm>
#include <cassert>

namespace trimkit::geom {

// [PT] Algorithm A2.1, by binary search over U[p+1 .. n].
// Departure (see header): u outside the domain is clamped to its ends, and the
// right end belongs to the last non-empty span ending at U[n+1].
int knot_span(const std::vector<double>& U, int p, double u) {
    const int n = static_cast<int>(U.size()) - p - 2;
    assert(n >= p && "knot vector shorter than 2(p+1)");
    if (!(u < U[n + 1])) {
        // Last i <= n with U[i] < U[n+1]; exists because U[p] < U[n+1].
        auto it = std::lower_bound(U.begin() + p, U.begin() + n + 1, U[n + 1]);
        return static_cast<int>(it - U.begin()) - 1;
    }
    if (u < U[p]) u = U[p];
    // First k in [p+1, n+1) with U[k] > u; the span is k - 1.
    auto it = std::upper_bound(U.begin() + p + 1, U.begin() + n + 1, u);
    return static_cast<int>(it - U.begin()) - 1;
}

// [PT] Algorithm A2.2: N[j] = N_{span-p+j,p}(u) by the triangular recurrence.
void basis_functions(const std::vector<double>& U, int p, int span, double u, double* N) {
    assert(p >= 0 && p <= kMaxDegree);
    double left[kMaxDegree + 1];
    double right[kMaxDegree + 1];
    N[0] = 1.0;
    for (int j = 1; j <= p; ++j) {
        left[j] = u - U[span + 1 - j];
        right[j] = U[span + j] - u;
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            const double temp = N[r] / (right[r + 1] + left[j - r]);
            N[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        N[j] = saved;
    }
}

// [PT] Algorithm A2.3. ndu holds the basis functions (upper triangle) and the
// knot differences (lower triangle); a holds two rows of the a_{k,j} coefficients.
// Departure: rows k > p are zero-filled (A2.3 assumes n <= p).
void basis_function_derivatives(const std::vector<double>& U, int p, int span, double u,
                                int n, double* ders) {
    assert(p >= 0 && p <= kMaxDegree && n >= 0);
    constexpr int kSize = kMaxDegree + 1;
    double ndu[kSize][kSize];
    double a[2][kSize];
    double left[kSize];
    double right[kSize];
    const int stride = p + 1;

    ndu[0][0] = 1.0;
    for (int j = 1; j <= p; ++j) {
        left[j] = u - U[span + 1 - j];
        right[j] = U[span + j] - u;
        double saved = 0.0;
        for (int r = 0; r < j; ++r) {
            ndu[j][r] = right[r + 1] + left[j - r];  // lower triangle: knot differences
            const double temp = ndu[r][j - 1] / ndu[j][r];
            ndu[r][j] = saved + right[r + 1] * temp;  // upper triangle: basis functions
            saved = left[j - r] * temp;
        }
        ndu[j][j] = saved;
    }
    for (int j = 0; j <= p; ++j) ders[j] = ndu[j][p];

    const int top = std::min(n, p);
    for (int r = 0; r <= p; ++r) {
        int s1 = 0, s2 = 1;
        a[0][0] = 1.0;
        for (int k = 1; k <= top; ++k) {
            double d = 0.0;
            const int rk = r - k, pk = p - k;
            if (r >= k) {
                a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
                d = a[s2][0] * ndu[rk][pk];
            }
            const int j1 = (rk >= -1) ? 1 : -rk;
            const int j2 = (r - 1 <= pk) ? k - 1 : p - r;
            for (int j = j1; j <= j2; ++j) {
                a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
                d += a[s2][j] * ndu[rk + j][pk];
            }
            if (r <= pk) {
                a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
                d += a[s2][k] * ndu[r][pk];
            }
            ders[k * stride + r] = d;
            std::swap(s1, s2);
        }
    }
    // Multiply through by p! / (p-k)!.
    double factor = p;
    for (int k = 1; k <= top; ++k) {
        for (int j = 0; j <= p; ++j) ders[k * stride + j] *= factor;
        factor *= (p - k);
    }
    for (int k = top + 1; k <= n; ++k)
        for (int j = 0; j <= p; ++j) ders[k * stride + j] = 0.0;
}

std::vector<std::vector<double>> basis_function_derivatives(
    const std::vector<double>& U, int p, int span, double u, int n) {
    std::vector<double> flat(static_cast<size_t>(n + 1) * (p + 1));
    basis_function_derivatives(U, p, span, u, n, flat.data());
    std::vector<std::vector<double>> ders(n + 1);
    for (int k = 0; k <= n; ++k)
        ders[k].assign(flat.begin() + k * (p + 1), flat.begin() + (k + 1) * (p + 1));
    return ders;
}

}  // namespace trimkit::geom
