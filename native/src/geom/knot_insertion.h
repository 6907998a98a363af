// Knot insertion ([PT] Ch. 5), written once for curves and surfaces. What depends on
// the knot vector alone is worked out once; it is then applied to each row of
// homogeneous control points Pw = (w P, w): a curve is one row, a surface has one row
// per column of its grid. H is the homogeneous point type (Eigen, fixed size).
#pragma once

#include <algorithm>
#include <vector>

#include <Eigen/Core>

namespace trimkit::geom {

template <int Dim>
using HomogeneousPoint = Eigen::Matrix<double, Dim + 1, 1>;

template <int Dim>
HomogeneousPoint<Dim> homogeneous(const Eigen::Matrix<double, Dim, 1>& P, double w) {
    HomogeneousPoint<Dim> h;
    h << w * P, w;
    return h;
}

// The Euclidean point of h. Not rational: w is exactly 1, so P is read off without a
// division (and the weights stay exactly 1).
template <int Dim>
Eigen::Matrix<double, Dim, 1> euclidean(const HomogeneousPoint<Dim>& h, bool rational) {
    return rational ? Eigen::Matrix<double, Dim, 1>(h.template head<Dim>() / h[Dim])
                    : Eigen::Matrix<double, Dim, 1>(h.template head<Dim>());
}

// [PT] Algorithm A5.1 for t inserted r times into the knots U of degree p, where
// U[k] <= t < U[k+1] and t had multiplicity s.
struct KnotInsertion {
    int p = 0, k = 0, s = 0, r = 0;
    std::vector<double> knots;   // U with t inserted r times
    std::vector<double> alpha;   // alpha_{i,j} at [(j - 1) * (p + 1) + i], j = 1..r
};

// t closer than kKnotTolerance (relative to the domain) to a knot is that knot; the
// multiplicity is capped at p, so r = min(times, p - s) (0: nothing to insert).
// Throws InvalidInput naming `owner` when times < 0 or t lies outside the domain.
KnotInsertion plan_knot_insertion(const std::vector<double>& U, int p, double t, int times,
                                  const char* owner);

// The row of control points after the insertion: P.size() + plan.r points.
template <class H>
std::vector<H> insert_knot(const KnotInsertion& plan, const std::vector<H>& P) {
    const int p = plan.p, k = plan.k, s = plan.s, r = plan.r, last = static_cast<int>(P.size()) - 1;
    if (r <= 0) return P;
    std::vector<H> Q(P.size() + r);
    for (int i = 0; i <= k - p; ++i) Q[i] = P[i];
    for (int i = k - s; i <= last; ++i) Q[i + r] = P[i];
    std::vector<H> R(P.begin() + (k - p), P.begin() + (k - s + 1));
    int L = k - p;
    for (int j = 1; j <= r; ++j) {
        L = k - p + j;
        const double* alpha = &plan.alpha[static_cast<size_t>(j - 1) * (p + 1)];
        for (int i = 0; i <= p - j - s; ++i) R[i] = alpha[i] * R[i + 1] + (1.0 - alpha[i]) * R[i];
        Q[L] = R[0];
        Q[k + r - j - s] = R[p - j - s];
    }
    for (int i = L + 1; i < k - s; ++i) Q[i] = R[i - L];
    return Q;
}

// The insertions that clamp the domain ends of U (each end knot raised to
// multiplicity p; none when already clamped), and the knot index range of the clamped
// domain: the row of points [first, end) has knots p+1 x a, the interior, p+1 x b.
struct DomainClamp {
    std::vector<KnotInsertion> insertions;
    std::vector<double> knots;   // p + 1 equal knots at each end
    std::vector<double> breaks;  // its distinct knots, breaks[0] < .. < breaks[n]: n pieces
    int first = 0, end = 0;
};
DomainClamp plan_domain_clamp(const std::vector<double>& U, int p, const char* owner);

// [PT] Algorithm A5.6 on the clamped row (ends clamped first when they are not):
// one Bézier piece per non-empty knot span (between clamp.breaks[q] and [q + 1]), its
// p + 1 points at [q * (p + 1), (q + 1) * (p + 1)); O(n p^2) for n points.
template <class H>
std::vector<H> bezier_pieces(const DomainClamp& clamp, int p, std::vector<H> P) {
    for (const KnotInsertion& plan : clamp.insertions) P = insert_knot(plan, P);
    const std::vector<double>& U = clamp.knots;
    const int m = static_cast<int>(U.size()) - 1;
    const size_t pieces = clamp.breaks.size() - 1, width = static_cast<size_t>(p) + 1;
    std::vector<H> out((pieces + 1) * width);
    auto Q = [&](size_t piece, int i) -> H& { return out[piece * width + i]; };
    for (int i = 0; i <= p; ++i) Q(0, i) = P[clamp.first + i];
    std::vector<double> alphas(width);
    int a = p, b = p + 1;
    size_t nb = 0;
    while (b < m) {
        const int i0 = b;
        while (b < m && U[b + 1] == U[b]) ++b;
        const int mult = b - i0 + 1;
        if (mult < p) {
            const double numer = U[b] - U[a];
            for (int j = p; j > mult; --j) alphas[j - mult - 1] = numer / (U[a + j] - U[a]);
            const int r = p - mult;
            for (int j = 1; j <= r; ++j) {
                const int save = r - j, s = mult + j;
                for (int k = p; k >= s; --k)
                    Q(nb, k) = alphas[k - s] * Q(nb, k) + (1.0 - alphas[k - s]) * Q(nb, k - 1);
                if (b < m) Q(nb + 1, save) = Q(nb, p);
            }
        }
        ++nb;
        if (b < m) {
            // A knot of multiplicity p + 1 (a break in the curve) starts a fresh piece.
            for (int i = std::max(0, p - mult); i <= p; ++i) Q(nb, i) = P[clamp.first + b - p + i];
            a = b;
            ++b;
        }
    }
    out.resize(pieces * width);
    return out;
}

}  // namespace trimkit::geom
