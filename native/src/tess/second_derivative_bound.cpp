#include "tess/second_derivative_bound.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace trimkit::tess {
namespace {

// Re-derived bound (the idea is the C^2 interpolation bound of Filip, Magedson and
// Markot, "Surface algorithms using bounds on derivatives", CAGD 3, 1986; the
// rational derivative bounds are ours).
//
// 1. Interpolation error. Let a_k be the (s,t) of a triangle's vertices in [0,1]^2,
//    lambda_k barycentric weights and p = sum lambda_k a_k. Taylor with integral
//    remainder along the segment p -> a_k, d_k = a_k - p:
//       S(a_k) = S(p) + DS(p) d_k + R_k,  |R_k| <= 1/2 (M_uu ds^2 + 2 M_uv |ds dt| + M_vv dt^2).
//    sum lambda_k d_k = 0, so |sum lambda_k S(a_k) - S(p)| <= sum lambda_k |R_k|, and with
//    sum lambda_k ds_k^2 = Var(s) <= 1/4 (values in [0,1]), sum lambda_k |ds_k dt_k| <=
//    sqrt(Var(s) Var(t)) <= 1/4 (Cauchy-Schwarz):
//       |sum lambda_k S(a_k) - S(p)| <= (M_uu + 2 M_uv + M_vv) / 8.
//    This holds for every triangle with vertices on S inside the patch, at the mesh's
//    own barycentric (s,t) -- the "S at the interpolated (u,v)" measure -- and in both
//    directions (mesh point -> S(p), S(p) -> mesh point).
//
// 2. Derivatives of S = H / w (H = xyz numerator, w = weight, both polynomial):
//       S_s = K / w^2,   K = w H_s - H w_s        (degree (2m-1, 2n))
//       S_t = L / w^2,   L = w H_t - H w_t
//       S_ss = K_s / w^2 - 2 S_s w_s / w,   S_tt = L_t / w^2 - 2 S_t w_t / w,
//       S_st = K_t / w^2 - 2 S_s w_t / w = L_s / w^2 - 2 S_t w_s / w.
//    K and L are invariant under translating S (w H_s - H w_s changes by
//    c (w w_s - w w_s) = 0), so the bound does not depend on where the origin is, and
//    they vanish where the weights are constant along a line of S that is straight
//    (a cylinder's rulings): on a cylinder K_t = 0 and w_t = 0, so M_uv = 0, and
//    M_uu is the arc's true |S_ss| up to (w_max / w_min)^2 -> 1 as the patch shrinks.
//    Every factor is bounded from control points (convex hull of Bernstein forms):
//    |K|, |K_s|, |K_t| by the largest control-point norm of K and of its difference
//    nets times the degree, |w_s| by m max |w_{i+1,j} - w_ij|, and w >= min w_ij > 0.
//
// K's Bernstein coefficients: products of Bernstein polynomials, per direction
//    (f g)_k = sum_{i + i' = k} C(a, i) C(b, i') / C(a + b, k) f_i g_i'
//    ([PT] Sec. 1.3 / Farin, product of Bernstein polynomials), with f = w
//    (degree (m, n)) and g = H_s (degree (m-1, n)), then minus H times w_s.

using Vec3 = Eigen::Vector3d;

struct Net {
    int du = 0, dv = 0;  // degrees
    std::vector<Vec3> c;
    const Vec3& at(int i, int j) const { return c[i * (dv + 1) + j]; }
};
struct ScalarNet {
    int du = 0, dv = 0;
    std::vector<double> c;
    double at(int i, int j) const { return c[i * (dv + 1) + j]; }
};

double binomial(int n, int k) {
    double r = 1.0;
    for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
    return r;
}

// The factors C(a, i) C(b, i') / C(a + b, i + i') of a Bernstein product, i <= a, i' <= b,
// row-major over (i, i').
std::vector<double> product_factors(int a, int b) {
    std::vector<double> out;
    out.reserve(static_cast<size_t>((a + 1) * (b + 1)));
    for (int i = 0; i <= a; ++i)
        for (int i2 = 0; i2 <= b; ++i2) out.push_back(binomial(a, i) * binomial(b, i2) / binomial(a + b, i + i2));
    return out;
}

// product_factors(a, b) for the degrees of a product f g with f of degree a and g of
// degree a - 1 or a (the only pairs numerator() forms), computed once per process for
// degrees up to kCachedDegree; other pairs are computed on the spot.
constexpr int kCachedDegree = 12;
const std::vector<double>& cached_product_factors(int a, int b, std::vector<double>& scratch) {
    static const std::vector<std::vector<double>> table = [] {
        std::vector<std::vector<double>> t((kCachedDegree + 1) * (kCachedDegree + 1));
        for (int x = 0; x <= kCachedDegree; ++x)
            for (int y = 0; y <= kCachedDegree; ++y) t[x * (kCachedDegree + 1) + y] = product_factors(x, y);
        return t;
    }();
    if (a <= kCachedDegree && b <= kCachedDegree) return table[a * (kCachedDegree + 1) + b];
    scratch = product_factors(a, b);
    return scratch;
}

// f * g for a scalar net f and a vector net g, in Bernstein form. The binomial
// factors are computed once per direction (the hot loop of the surface bound).
Net product(const ScalarNet& f, const Net& g) {
    Net out;
    out.du = f.du + g.du;
    out.dv = f.dv + g.dv;
    out.c.assign((out.du + 1) * (out.dv + 1), Vec3::Zero());
    std::vector<double> scratch_u, scratch_v;
    const std::vector<double>& fu = cached_product_factors(f.du, g.du, scratch_u);
    const std::vector<double>& fv = cached_product_factors(f.dv, g.dv, scratch_v);
    for (int i = 0; i <= f.du; ++i)
        for (int i2 = 0; i2 <= g.du; ++i2) {
            const double cu = fu[i * (g.du + 1) + i2];
            for (int j = 0; j <= f.dv; ++j) {
                const double fij = f.at(i, j);
                Vec3* row = &out.c[(i + i2) * (out.dv + 1) + j];
                for (int j2 = 0; j2 <= g.dv; ++j2)
                    row[j2] += cu * fv[j * (g.dv + 1) + j2] * fij * g.at(i2, j2);
            }
        }
    return out;
}

// Largest |control point| of the net, and of its s- and t-derivative nets.
double max_norm(const Net& n) {
    double r = 0.0;
    for (const Vec3& v : n.c) r = std::max(r, v.norm());
    return r;
}
double max_derivative_norm(const Net& n, bool in_s) {
    const int d = in_s ? n.du : n.dv;
    if (d == 0) return 0.0;
    double r = 0.0;
    for (int i = 0; i + (in_s ? 1 : 0) <= n.du; ++i)
        for (int j = 0; j + (in_s ? 0 : 1) <= n.dv; ++j)
            r = std::max(r, (n.at(i + (in_s ? 1 : 0), j + (in_s ? 0 : 1)) - n.at(i, j)).norm());
    return d * r;
}

// K = w H_s - H w_s (in_s) or L = w H_t - H w_t.
Net numerator(const BezierPatch& patch, bool in_s) {
    const int m = patch.p, n = patch.q;
    ScalarNet w{m, n, {}};
    Net H{m, n, {}};
    for (int i = 0; i <= m; ++i)
        for (int j = 0; j <= n; ++j) {
            w.c.push_back(patch.point(i, j)[3]);
            H.c.push_back(patch.point(i, j).head<3>());
        }
    ScalarNet w_d{in_s ? m - 1 : m, in_s ? n : n - 1, {}};
    Net H_d{w_d.du, w_d.dv, {}};
    const int d = in_s ? m : n;
    for (int i = 0; i <= w_d.du; ++i)
        for (int j = 0; j <= w_d.dv; ++j) {
            const int i1 = i + (in_s ? 1 : 0), j1 = j + (in_s ? 0 : 1);
            w_d.c.push_back(d * (w.at(i1, j1) - w.at(i, j)));
            H_d.c.push_back(d * (H.at(i1, j1) - H.at(i, j)));
        }
    Net K = product(w, H_d);
    // H w_d = w_d H: the same product with the roles swapped.
    const Net minus = product(w_d, H);
    for (size_t k = 0; k < K.c.size(); ++k) K.c[k] -= minus.c[k];
    return K;
}

double max_weight_derivative(const BezierPatch& patch, bool in_s) {
    const int m = patch.p, n = patch.q, d = in_s ? m : n;
    double r = 0.0;
    for (int i = 0; i + (in_s ? 1 : 0) <= m; ++i)
        for (int j = 0; j + (in_s ? 0 : 1) <= n; ++j)
            r = std::max(r, std::abs(patch.point(i + (in_s ? 1 : 0), j + (in_s ? 0 : 1))[3] -
                                     patch.point(i, j)[3]));
    return d * r;
}

}  // namespace

SecondDerivativeBound second_derivative_bound(const BezierPatch& patch) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    double w_min = kInf;
    for (const Eigen::Vector4d& P : patch.Pw) w_min = std::min(w_min, P[3]);
    if (!(w_min > 0.0) || !std::isfinite(w_min)) return {kInf, kInf, kInf};
    const Net K = numerator(patch, true), L = numerator(patch, false);
    const double w2 = w_min * w_min;
    const double M_s = max_norm(K) / w2, M_t = max_norm(L) / w2;  // sup |S_s|, |S_t|
    const double W_s = max_weight_derivative(patch, true), W_t = max_weight_derivative(patch, false);
    SecondDerivativeBound b;
    b.M_uu = max_derivative_norm(K, true) / w2 + 2.0 * M_s * W_s / w_min;
    b.M_vv = max_derivative_norm(L, false) / w2 + 2.0 * M_t * W_t / w_min;
    b.M_uv = std::min(max_derivative_norm(K, false) / w2 + 2.0 * M_s * W_t / w_min,
                      max_derivative_norm(L, true) / w2 + 2.0 * M_t * W_s / w_min);
    if (!std::isfinite(b.error())) return {kInf, kInf, kInf};
    return b;
}

}  // namespace trimkit::tess
