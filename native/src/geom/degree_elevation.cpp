#include "geom/degree_elevation.h"

#include <algorithm>
#include <string>
#include <vector>

#include "geom/bspline_basis.h"
#include "geom/error.h"
#include "geom/knot_vector.h"

namespace trimkit::geom {

namespace {

double binomial(int n, int k) {
    double b = 1;
    for (int i = 1; i <= k; ++i) b = b * (n - k + i) / i;
    return b;
}

}  // namespace

// [PT] Algorithm A5.9 (DegreeElevateCurve), variable names as in the book:
// Bézier segments are extracted by knot insertion, elevated with the
// coefficients bezalfs, and knots between them removed again (oldr times).
template <int Dim>
NurbsCurve<Dim> elevate_degree(const NurbsCurve<Dim>& curve, int t) {
    if (t < 0) throw InvalidInput("elevate_degree: t = " + std::to_string(t) + "; expected >= 0");
    if (t == 0) return curve;
    if (curve.degree() + t > kMaxDegree) {
        throw InvalidInput("elevate_degree: degree " + std::to_string(curve.degree()) + " + " +
                           std::to_string(t) + " exceeds kMaxDegree = " +
                           std::to_string(kMaxDegree));
    }
    const auto [lo, hi] = curve.domain();
    const NurbsCurve<Dim> c = is_clamped(curve.knots(), curve.degree()) ? curve
                                                                        : curve.sub_curve(lo, hi);
    using HPoint = Eigen::Matrix<double, Dim + 1, 1>;
    const std::vector<double>& U = c.knots();
    const int p = c.degree();
    const int n = static_cast<int>(c.points().size()) - 1;
    std::vector<HPoint> Pw(n + 1);
    for (int i = 0; i <= n; ++i) Pw[i] << c.weights()[i] * c.points()[i], c.weights()[i];

    const int m = n + p + 1;
    const int ph = p + t, ph2 = ph / 2;
    // Bézier degree elevation coefficients.
    std::vector<std::vector<double>> bezalfs(ph + 1, std::vector<double>(p + 1, 0.0));
    bezalfs[0][0] = bezalfs[ph][p] = 1.0;
    for (int i = 1; i <= ph2; ++i) {
        const double inv = 1.0 / binomial(ph, i);
        const int mpi = std::min(p, i);
        for (int j = std::max(0, i - t); j <= mpi; ++j)
            bezalfs[i][j] = inv * binomial(p, j) * binomial(t, i - j);
    }
    for (int i = ph2 + 1; i <= ph - 1; ++i) {
        const int mpi = std::min(p, i);
        for (int j = std::max(0, i - t); j <= mpi; ++j) bezalfs[i][j] = bezalfs[ph - i][p - j];
    }
    // Upper bounds: every distinct knot gains t copies, every segment t points.
    const int segments = m;  // > number of non-empty spans
    std::vector<double> Uh(U.size() + static_cast<size_t>(t) * (segments + 1));
    std::vector<HPoint> Qw(Pw.size() + static_cast<size_t>(t) * (segments + 1));
    std::vector<HPoint> bpts(p + 1), ebpts(ph + 1), Nextbpts(std::max(p - 1, 1));
    std::vector<double> alfs(std::max(p - 1, 1));

    int mh = ph, kind = ph + 1;
    int r = -1, a = p, b = p + 1, cind = 1;
    double ua = U[0];
    Qw[0] = Pw[0];
    for (int i = 0; i <= ph; ++i) Uh[i] = ua;
    for (int i = 0; i <= p; ++i) bpts[i] = Pw[i];
    while (b < m) {
        int i = b;
        while (b < m && U[b] == U[b + 1]) ++b;
        const int mul = b - i + 1;
        mh += mul + t;
        const double ub = U[b];
        const int oldr = r;
        r = p - mul;
        const int lbz = oldr > 0 ? (oldr + 2) / 2 : 1;
        const int rbz = r > 0 ? ph - (r + 1) / 2 : ph;
        if (r > 0) {  // insert ub r times to finish the Bézier segment
            const double numer = ub - ua;
            for (int k = p; k > mul; --k) alfs[k - mul - 1] = numer / (U[a + k] - ua);
            for (int j = 1; j <= r; ++j) {
                const int save = r - j, s = mul + j;
                for (int k = p; k >= s; --k)
                    bpts[k] = alfs[k - s] * bpts[k] + (1.0 - alfs[k - s]) * bpts[k - 1];
                Nextbpts[save] = bpts[p];
            }
        }
        for (int ii = lbz; ii <= ph; ++ii) {  // elevate the Bézier segment
            ebpts[ii].setZero();
            const int mpi = std::min(p, ii);
            for (int j = std::max(0, ii - t); j <= mpi; ++j) ebpts[ii] += bezalfs[ii][j] * bpts[j];
        }
        if (oldr > 1) {  // remove knot ua oldr - 1 times
            int first = kind - 2, last = kind;
            const double den = ub - ua;
            const double bet = (ub - Uh[kind - 1]) / den;
            for (int tr = 1; tr < oldr; ++tr) {
                int ii = first, j = last, kj = j - kind + 1;
                while (j - ii > tr) {
                    if (ii < cind) {
                        const double alf = (ub - Uh[ii]) / (ua - Uh[ii]);
                        Qw[ii] = alf * Qw[ii] + (1.0 - alf) * Qw[ii - 1];
                    }
                    if (j >= lbz) {
                        if (j - tr <= kind - ph + oldr) {
                            const double gam = (ub - Uh[j - tr]) / den;
                            ebpts[kj] = gam * ebpts[kj] + (1.0 - gam) * ebpts[kj + 1];
                        } else {
                            ebpts[kj] = bet * ebpts[kj] + (1.0 - bet) * ebpts[kj + 1];
                        }
                    }
                    ++ii;
                    --j;
                    --kj;
                }
                --first;
                ++last;
            }
        }
        if (a != p)  // load the knot ua
            for (int ii = 0; ii < ph - oldr; ++ii) Uh[kind++] = ua;
        for (int j = lbz; j <= rbz; ++j) Qw[cind++] = ebpts[j];
        if (b < m) {  // set up the next pass
            for (int j = 0; j < r; ++j) bpts[j] = Nextbpts[j];
            for (int j = r; j <= p; ++j) bpts[j] = Pw[b - p + j];
            a = b;
            ++b;
            ua = ub;
        } else {
            for (int ii = 0; ii <= ph; ++ii) Uh[kind + ii] = ub;
        }
    }
    const int nh = mh - ph - 1;
    Uh.resize(nh + ph + 2);
    std::vector<typename NurbsCurve<Dim>::Point> Q(nh + 1);
    std::vector<double> w(nh + 1);
    for (int i = 0; i <= nh; ++i) {
        if (!c.is_rational()) {  // weights stay exactly 1
            Q[i] = Qw[i].template head<Dim>();
            continue;
        }
        w[i] = Qw[i][Dim];
        if (!(w[i] > 0))
            throw NumericalFailure("elevate_degree: elevated weight " + std::to_string(i) +
                                   " is not positive");
        Q[i] = Qw[i].template head<Dim>() / w[i];
    }
    return NurbsCurve<Dim>(ph, std::move(Uh), std::move(Q),
                           c.is_rational() ? std::move(w) : std::vector<double>{});
}

template NurbsCurve<2> elevate_degree(const NurbsCurve<2>&, int);
template NurbsCurve<3> elevate_degree(const NurbsCurve<3>&, int);

}  // namespace trimkit::geom
