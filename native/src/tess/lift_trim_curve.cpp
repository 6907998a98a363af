// [Balazs] Sec. 4: trim curves cut at knot lines and lifted to exact 3D Bézier curves.
#include "tess/lift_trim_curve.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <mutex>

#include <Eigen/Dense>

#include "geom/bspline_basis.h"
#include "geom/knot_vector.h"
#include "geom/homogeneous_bezier.h"

namespace trimkit::tess {

using geom::bezier_piece;
using geom::de_casteljau;
using geom::project;
using geom::split_bezier;

namespace {

// Root isolation depth: 2^-48 of a segment is below double resolution of t.
constexpr int kMaxRootDepth = 48;
// Bernstein coefficients below this fraction of the curve's size count as zero
// (the segment runs along the knot line: no crossing to cut at).
constexpr double kZeroCoefficientRelative = 1e-13;

double binomial(int n, int k) {
    double r = 1.0;
    for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
    return r;
}

double bernstein(int n, int i, double s) {
    return binomial(n, i) * std::pow(s, i) * std::pow(1.0 - s, n - i);
}

// Roots in (a, b) of the polynomial with Bernstein coefficients f over [a, b].
void bernstein_roots(const std::vector<double>& f, double a, double b, int depth,
                     std::vector<double>* roots) {
    bool positive = true, negative = true;
    for (double x : f) {
        positive = positive && x > 0.0;
        negative = negative && x < 0.0;
    }
    if (positive || negative) return;
    if (depth >= kMaxRootDepth) {
        roots->push_back(0.5 * (a + b));
        return;
    }
    std::vector<Eigen::Matrix<double, 1, 1>> P(f.size()), L, R;
    for (size_t i = 0; i < f.size(); ++i) P[i](0) = f[i];
    split_bezier(P, 0.5, &L, &R);
    std::vector<double> fl(f.size()), fr(f.size());
    for (size_t i = 0; i < f.size(); ++i) {
        fl[i] = L[i](0);
        fr[i] = R[i](0);
    }
    const double m = 0.5 * (a + b);
    bernstein_roots(fl, a, m, depth + 1, roots);
    bernstein_roots(fr, m, b, depth + 1, roots);
}

// Distinct knots strictly inside the domain.
std::vector<double> interior_knots(const std::vector<double>& U, int p) {
    std::vector<double> k = geom::distinct_knots(U, p);
    if (k.size() <= 2) return {};
    return std::vector<double>(k.begin() + 1, k.end() - 1);
}

// Denominator w(t) = sum N_i(t) w_i of a rational curve (1 if polynomial).
double curve_weight(const geom::NurbsCurve2d& c, double t) {
    if (!c.is_rational()) return 1.0;
    const int p = c.degree();
    const auto [a, b] = c.domain();
    t = std::clamp(t, a, b);
    const int span = geom::knot_span(c.knots(), p, t);
    double N[geom::kMaxDegree + 1];
    geom::basis_functions(c.knots(), p, span, t, N);
    double w = 0.0;
    for (int i = 0; i <= p; ++i) w += N[i] * c.weights()[span - p + i];
    return w;
}

// Denominator w_S(u, v) of a rational surface (1 if polynomial).
double surface_weight(const geom::NurbsSurface& S, double u, double v) {
    if (!S.is_rational()) return 1.0;
    const int p = S.degree_u(), q = S.degree_v();
    const auto [u0, u1] = S.domain_u();
    const auto [v0, v1] = S.domain_v();
    u = std::clamp(u, u0, u1);
    v = std::clamp(v, v0, v1);
    const int su = geom::knot_span(S.knots_u(), p, u), sv = geom::knot_span(S.knots_v(), q, v);
    double Nu[geom::kMaxDegree + 1], Nv[geom::kMaxDegree + 1];
    geom::basis_functions(S.knots_u(), p, su, u, Nu);
    geom::basis_functions(S.knots_v(), q, sv, v, Nv);
    double w = 0.0;
    for (int i = 0; i <= p; ++i)
        for (int j = 0; j <= q; ++j) w += Nu[i] * Nv[j] * S.weight(su - p + i, sv - q + j);
    return w;
}

// Degree n-1 candidate for Q (degree n): the inverse of degree elevation from the
// left for the first half and from the right for the second, averaged at the middle.
// [Balazs] Sec. 4 after [Far96]; indices re-derived from Q_i = (i/n) R_{i-1} + (1 - i/n) R_i.
std::vector<Eigen::Vector4d> reduce_degree(const std::vector<Eigen::Vector4d>& Q) {
    const int n = static_cast<int>(Q.size()) - 1;
    std::vector<Eigen::Vector4d> L(n), R(n), out(n);
    L[0] = Q[0];
    for (int i = 1; i < n; ++i) L[i] = (Q[i] - (double(i) / n) * L[i - 1]) / (1.0 - double(i) / n);
    R[n - 1] = Q[n];
    for (int i = n - 1; i >= 1; --i) R[i - 1] = (Q[i] - (1.0 - double(i) / n) * R[i]) / (double(i) / n);
    for (int i = 0; i < n; ++i) {
        const double half = 0.5 * (n - 1);
        out[i] = i < half ? L[i] : i > half ? R[i] : 0.5 * (L[i] + R[i]);
    }
    return out;
}

// Largest distance between the Bézier H and the Euclidean samples X at s.
double max_deviation(const std::vector<Eigen::Vector4d>& H, const std::vector<double>& s,
                     const std::vector<Eigen::Vector3d>& X) {
    double e = 0.0;
    for (size_t k = 0; k < s.size(); ++k) {
        const Eigen::Vector4d h = de_casteljau(H, s[k]);
        if (!(h.w() > 0.0)) return std::numeric_limits<double>::infinity();
        e = std::max(e, (project(h) - X[k]).norm());
    }
    return e;
}

// The pseudo-inverse of the Bernstein collocation matrix A(k, j) = B_j^n(k/n), by SVD:
// A depends on n alone, so each lift is one product instead of one SVD (the lifts were
// a fifth of a STEP file's meshing time). Each degree is computed on its first use: all
// 24 at once cost 2.3 ms, the whole meshing time of a small part.
Eigen::MatrixXd collocation_pseudo_inverse(int n) {
    Eigen::MatrixXd A(n + 1, n + 1);
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j) A(k, j) = bernstein(n, j, double(k) / n);
    return Eigen::JacobiSVD<Eigen::MatrixXd>(A, Eigen::ComputeThinU | Eigen::ComputeThinV)
        .solve(Eigen::MatrixXd::Identity(n + 1, n + 1));
}

const Eigen::MatrixXd& collocation_inverse(int n) {
    static std::array<std::once_flag, kMaxLiftDegree + 1> computed;
    static std::array<Eigen::MatrixXd, kMaxLiftDegree + 1> table;
    std::call_once(computed[n], [n] { table[n] = collocation_pseudo_inverse(n); });
    return table[n];
}

LiftedPiece lift_piece(const geom::NurbsSurface& S, const geom::NurbsCurve2d& c, double t0,
                       double t1) {
    LiftedPiece piece;
    piece.t0 = t0;
    piece.t1 = t1;
    const int e = S.degree_u() + S.degree_v();
    const int d3d_full = c.degree() * e;
    const int n = std::min(d3d_full, kMaxLiftDegree);

    auto sample = [&](double s, Eigen::Vector4d* h, Eigen::Vector3d* x) {
        const double t = piece.parameter(s);
        const Eigen::Vector2d uv = c.evaluate(t);
        *x = S.evaluate(uv.x(), uv.y());
        const double w = std::pow(curve_weight(c, t), e) * surface_weight(S, uv.x(), uv.y());
        *h << w * *x, w;
    };
    // Fit samples s_k = k/n; check samples: the fit samples and the midpoints.
    Eigen::MatrixXd rhs(n + 1, 4);
    std::vector<double> check_s;
    std::vector<Eigen::Vector3d> check_x;
    Eigen::AlignedBox3d box;
    double w_scale = 0.0;
    for (int k = 0; k <= n; ++k) {
        const double s = double(k) / n;
        Eigen::Vector4d h;
        Eigen::Vector3d x;
        sample(s, &h, &x);
        rhs.row(k) = h.transpose();
        w_scale = std::max(w_scale, h.w());
        check_s.push_back(s);
        check_x.push_back(x);
        box.extend(x);
    }
    for (int k = 0; k < n; ++k) {
        Eigen::Vector4d h;
        Eigen::Vector3d x;
        sample((k + 0.5) / n, &h, &x);
        check_s.push_back((k + 0.5) / n);
        check_x.push_back(x);
        box.extend(x);
    }
    rhs /= w_scale;  // any common factor of a homogeneous curve; keeps w ~ 1
    const Eigen::MatrixXd sol = collocation_inverse(n) * rhs;
    piece.P.resize(n + 1);
    for (int j = 0; j <= n; ++j) piece.P[j] = sol.row(j).transpose();

    // Size for relative tolerances; the rounding floor keeps a collapsed piece
    // (a pole) from demanding more than double precision of its coordinates.
    const double floor = 64.0 * std::numeric_limits<double>::epsilon() *
                         (box.min().cwiseAbs().maxCoeff() + box.max().cwiseAbs().maxCoeff());
    const double size = box.diagonal().norm();
    const double reduce_tol = kReductionTolerance * size + floor;
    while (piece.P.size() > 1) {
        std::vector<Eigen::Vector4d> R = reduce_degree(piece.P);
        if (max_deviation(R, check_s, check_x) > reduce_tol) break;
        piece.P = std::move(R);
    }
    piece.exact = d3d_full <= kMaxLiftDegree &&
                  max_deviation(piece.P, check_s, check_x) <= kLiftTolerance * size + floor;
    return piece;
}

}  // namespace

Eigen::Vector3d LiftedPiece::evaluate(double s) const { return project(de_casteljau(P, s)); }

std::vector<double> trim_curve_breaks(const geom::NurbsSurface& S, const geom::NurbsCurve2d& c) {
    const auto [ta, tb] = c.domain();
    std::vector<double> breaks = geom::distinct_knots(c.knots(), c.degree());
    const std::vector<double> knot_lines[2] = {interior_knots(S.knots_u(), S.degree_u()),
                                               interior_knots(S.knots_v(), S.degree_v())};
    const double size = c.control_box().diagonal().norm() +
                        c.control_box().min().cwiseAbs().maxCoeff();
    for (const geom::NurbsCurve2d& seg : c.bezier_segments()) {
        const auto [a, b] = seg.domain();
        const geom::NurbsCurve2d::Box box = seg.control_box();
        for (int dir = 0; dir < 2; ++dir)
            for (double K : knot_lines[dir]) {
                if (K < box.min()(dir) || K > box.max()(dir)) continue;
                std::vector<double> f(seg.points().size());
                double f_max = 0.0;
                for (size_t i = 0; i < f.size(); ++i) {
                    f[i] = seg.weights()[i] * (seg.points()[i](dir) - K);
                    f_max = std::max(f_max, std::abs(f[i]));
                }
                if (f_max <= kZeroCoefficientRelative * size) continue;
                std::vector<double> roots;
                bernstein_roots(f, a, b, 0, &roots);
                breaks.insert(breaks.end(), roots.begin(), roots.end());
            }
    }
    std::sort(breaks.begin(), breaks.end());
    const double merge = kBreakMergeRelative * (tb - ta);
    std::vector<double> merged;
    for (double t : breaks) {
        t = std::clamp(t, ta, tb);
        if (merged.empty() || t - merged.back() > merge) merged.push_back(t);
    }
    // The ends are exact: a break that merged into them is dropped, not kept.
    merged.front() = ta;
    if (merged.size() > 1 && tb - merged.back() <= merge) merged.back() = tb;
    else merged.push_back(tb);
    return merged;
}

std::vector<LiftedPiece> lift_trim_curve(const geom::NurbsSurface& S, const geom::NurbsCurve2d& c) {
    const std::vector<double> breaks = trim_curve_breaks(S, c);
    std::vector<LiftedPiece> pieces;
    for (size_t i = 0; i + 1 < breaks.size(); ++i)
        pieces.push_back(lift_piece(S, c, breaks[i], breaks[i + 1]));
    return pieces;
}

}  // namespace trimkit::tess
