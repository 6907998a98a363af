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

double binomial(int n, int k) {
    double r = 1.0;
    for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
    return r;
}

// A homogeneous Bernstein net with each coefficient times C(du, i) C(dv, j), one array
// per coordinate. With the binomials moved out of the sum, Farin's product
// (f g)_k = sum_{i + i' = k} C(a, i) C(b, i') / C(a + b, k) f_i g_i' is a plain
// convolution of scaled nets, divided by C(a + b, k) at the end.
struct ScaledNet {
    int du = 0, dv = 0;
    std::vector<double> x, y, z, w;  // row-major over (i, j)
    void resize(int u, int v) {
        du = u;
        dv = v;
        for (std::vector<double>* c : {&x, &y, &z, &w}) c->assign(static_cast<size_t>((u + 1) * (v + 1)), 0.0);
    }
    void set(int i, int j, const Eigen::Vector4d& P, double scale) {
        const size_t k = static_cast<size_t>(i * (dv + 1) + j);
        x[k] = scale * P[0];
        y[k] = scale * P[1];
        z[k] = scale * P[2];
        w[k] = scale * P[3];
    }
};

// The patch's net (in_s: false) or its s- or t-derivative net (in_s: true / false,
// `derivative` set), scaled as ScaledNet.
ScaledNet scaled_net(const BezierPatch& patch, bool derivative, bool in_s) {
    const int m = patch.p, n = patch.q;
    const int du = derivative && in_s ? m - 1 : m, dv = derivative && !in_s ? n - 1 : n;
    ScaledNet out;
    out.resize(du, dv);
    for (int i = 0; i <= du; ++i)
        for (int j = 0; j <= dv; ++j) {
            const double scale = binomial(du, i) * binomial(dv, j);
            if (!derivative) {
                out.set(i, j, patch.point(i, j), scale);
                continue;
            }
            const int i1 = i + (in_s ? 1 : 0), j1 = j + (in_s ? 0 : 1);
            out.set(i, j, (in_s ? m : n) * (patch.point(i1, j1) - patch.point(i, j)), scale);
        }
    return out;
}

// out[k] += a d[k] - b e[k] for k < n: the convolution's inner loop, over arrays that
// do not overlap (so that the compiler may vectorise it).
void multiply_add_row(int n, double a, const double* __restrict d, double b, const double* __restrict e,
                      double* __restrict out) {
    for (int k = 0; k < n; ++k) out[k] += a * d[k] - b * e[k];
}

// K = w H_s - H w_s (in_s) or L = w H_t - H w_t, in Bernstein form of degree
// (2m - 1, 2n) or (2m, 2n - 1): both products in one convolution of the scaled nets
// of P = (H, w) and of its derivative D (H w_d = w_d H, so both pair P's index with D's).
Net numerator(const BezierPatch& patch, bool in_s) {
    const ScaledNet P = scaled_net(patch, false, in_s), D = scaled_net(patch, true, in_s);
    const int ku = P.du + D.du, kv = P.dv + D.dv;
    std::vector<double> kx((ku + 1) * (kv + 1), 0.0), ky(kx), kz(kx);
    for (int i = 0; i <= P.du; ++i)
        for (int j = 0; j <= P.dv; ++j) {
            const size_t p = static_cast<size_t>(i * (P.dv + 1) + j);
            const double pw = P.w[p], px = P.x[p], py = P.y[p], pz = P.z[p];
            for (int i2 = 0; i2 <= D.du; ++i2) {
                const size_t d = static_cast<size_t>(i2 * (D.dv + 1)), k = static_cast<size_t>((i + i2) * (kv + 1) + j);
                multiply_add_row(D.dv + 1, pw, &D.x[d], px, &D.w[d], &kx[k]);
                multiply_add_row(D.dv + 1, pw, &D.y[d], py, &D.w[d], &ky[k]);
                multiply_add_row(D.dv + 1, pw, &D.z[d], pz, &D.w[d], &kz[k]);
            }
        }
    Net K{ku, kv, {}};
    K.c.reserve(kx.size());
    for (int k = 0; k <= ku; ++k)
        for (int l = 0; l <= kv; ++l) {
            const size_t c = static_cast<size_t>(k * (kv + 1) + l);
            K.c.emplace_back(Vec3(kx[c], ky[c], kz[c]) / (binomial(ku, k) * binomial(kv, l)));
        }
    return K;
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
