#include "geom/compatible_curves.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "geom/degree_elevation.h"
#include "geom/error.h"
#include "geom/knot_vector.h"

namespace trimkit::geom {

namespace {

// (value, multiplicity) of the distinct knots of a clamped curve on [0, 1].
std::vector<std::pair<double, int>> knot_counts(const std::vector<double>& U) {
    std::vector<std::pair<double, int>> counts;
    for (double u : U) {
        if (!counts.empty() && std::abs(u - counts.back().first) <= kKnotTolerance)
            ++counts.back().second;
        else
            counts.emplace_back(u, 1);
    }
    return counts;
}

// c with every knot of `target` present at least as often as there.
template <int Dim>
NurbsCurve<Dim> with_knots_of(NurbsCurve<Dim> c, const std::vector<double>& target) {
    const auto own = knot_counts(c.knots());
    for (const auto& [u, mult] : knot_counts(target)) {
        int have = 0;
        for (const auto& [v, m] : own)
            if (std::abs(u - v) <= kKnotTolerance) have = m;
        // insert_knot snaps u onto an existing knot within tolerance.
        if (mult > have) c = c.insert_knot(u, mult - have);
    }
    return c;
}

}  // namespace

template <int Dim>
std::pair<NurbsCurve<Dim>, NurbsCurve<Dim>> make_compatible(const NurbsCurve<Dim>& a,
                                                            const NurbsCurve<Dim>& b) {
    const int p = std::max(a.degree(), b.degree());
    // Clamping (inside elevate_degree / sub_curve) and [0, 1] first, so knots compare.
    auto prepare = [p](const NurbsCurve<Dim>& c) {
        const auto [lo, hi] = c.domain();
        NurbsCurve<Dim> r = c.sub_curve(lo, hi);
        r = elevate_degree(r, p - r.degree());
        return r.reparameterized(0.0, 1.0);
    };
    NurbsCurve<Dim> A = prepare(a), B = prepare(b);
    A = with_knots_of(A, B.knots());
    B = with_knots_of(B, A.knots());
    if (A.knots().size() != B.knots().size()) {
        throw NumericalFailure("make_compatible: merged knot vectors have " +
                               std::to_string(A.knots().size()) + " and " +
                               std::to_string(B.knots().size()) + " knots");
    }
    for (size_t i = 0; i < A.knots().size(); ++i) {
        if (std::abs(A.knots()[i] - B.knots()[i]) > kKnotTolerance) {
            throw NumericalFailure("make_compatible: merged knot " + std::to_string(i) +
                                   " differs between the curves");
        }
    }
    // Same values exactly: rebuild B on A's knots (they differ by < kKnotTolerance).
    B = NurbsCurve<Dim>(p, A.knots(), B.points(),
                        B.is_rational() ? B.weights() : std::vector<double>{});
    return {A, B};
}

namespace {

double binomial(int n, int k) {
    double r = 1;
    for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
    return r;
}

// Bernstein coefficients of the product of two degree-p Bézier functions
// (vector-valued f times scalar g): c_k = Σ_{i+j=k} C(p,i) C(p,j) / C(2p,k) f_i g_j.
template <class V>
std::vector<V> bernstein_product(const std::vector<V>& f, const std::vector<double>& g) {
    const int p = static_cast<int>(f.size()) - 1;
    std::vector<V> c(2 * p + 1, V::Zero());
    for (int i = 0; i <= p; ++i)
        for (int j = 0; j <= p; ++j)
            c[i + j] += (binomial(p, i) * binomial(p, j) / binomial(2 * p, i + j) * g[j]) * f[i];
    return c;
}

}  // namespace

template <int Dim>
std::pair<NurbsCurve<Dim>, NurbsCurve<Dim>> make_compatible_weights(const NurbsCurve<Dim>& a,
                                                                    const NurbsCurve<Dim>& b) {
    if (a.degree() != b.degree() || a.knots() != b.knots()) {
        throw InvalidInput("make_compatible_weights: curves of degree " +
                           std::to_string(a.degree()) + " and " + std::to_string(b.degree()) +
                           " with " + std::to_string(a.knots().size()) + " and " +
                           std::to_string(b.knots().size()) +
                           " knots are not compatible; call make_compatible first");
    }
    bool same = true;
    for (size_t i = 0; i < a.weights().size(); ++i)
        same = same && a.weights()[i] == b.weights()[i];
    if (same) return {a, b};

    using HPoint = Eigen::Matrix<double, Dim + 1, 1>;
    using Weight = Eigen::Matrix<double, 1, 1>;
    const int p = a.degree(), q = 2 * p;
    const auto sa = a.bezier_segments(), sb = b.bezier_segments();
    std::vector<double> U(q + 1, sa.front().domain().first);
    std::vector<HPoint> Aw, Bw;
    std::vector<double> W;
    for (size_t k = 0; k < sa.size(); ++k) {
        std::vector<HPoint> ha(p + 1), hb(p + 1);
        std::vector<double> wa(p + 1), wb(p + 1);
        std::vector<Weight> wa1(p + 1);
        for (int i = 0; i <= p; ++i) {
            wa[i] = sa[k].weights()[i];
            wb[i] = sb[k].weights()[i];
            wa1[i] << wa[i];
            ha[i] << wa[i] * sa[k].points()[i], wa[i];
            hb[i] << wb[i] * sb[k].points()[i], wb[i];
        }
        const auto pa = bernstein_product(ha, wb);   // (A_a W_b, W_a W_b)
        const auto pb = bernstein_product(hb, wa);   // (A_b W_a, W_b W_a)
        const auto pw = bernstein_product(wa1, wb);  // W_a W_b, one value for both
        for (int i = (k == 0 ? 0 : 1); i <= q; ++i) {
            Aw.push_back(pa[i]);
            Bw.push_back(pb[i]);
            W.push_back(pw[i][0]);
        }
        U.insert(U.end(), k + 1 < sa.size() ? q : q + 1, sa[k].domain().second);
    }
    std::vector<typename NurbsCurve<Dim>::Point> PA(W.size()), PB(W.size());
    for (size_t i = 0; i < W.size(); ++i) {
        PA[i] = Aw[i].template head<Dim>() / W[i];
        PB[i] = Bw[i].template head<Dim>() / W[i];
    }
    return {NurbsCurve<Dim>(q, U, std::move(PA), W), NurbsCurve<Dim>(q, U, std::move(PB), W)};
}

template std::pair<NurbsCurve<2>, NurbsCurve<2>> make_compatible_weights(const NurbsCurve<2>&,
                                                                         const NurbsCurve<2>&);
template std::pair<NurbsCurve<3>, NurbsCurve<3>> make_compatible_weights(const NurbsCurve<3>&,
                                                                         const NurbsCurve<3>&);

template std::pair<NurbsCurve<2>, NurbsCurve<2>> make_compatible(const NurbsCurve<2>&,
                                                                 const NurbsCurve<2>&);
template std::pair<NurbsCurve<3>, NurbsCurve<3>> make_compatible(const NurbsCurve<3>&,
                                                                 const NurbsCurve<3>&);

}  // namespace trimkit::geom
