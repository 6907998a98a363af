// NurbsSurface: validation, evaluation ([PT] Ch. 3-4) and knot insertion based
// operations ([PT] Ch. 5). Rational operations work on homogeneous points
// Pw = (w P, w). Operations along v are the u operations on swapped_uv().
#include "geom/nurbs_surface.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "geom/bspline_basis.h"
#include "geom/error.h"
#include "geom/rational_weights.h"
#include "geom/knot_insertion.h"
#include "geom/knot_vector.h"

namespace trimkit::geom {

namespace {

// normal(): Su (or Sv) counts as vanished when shorter than this fraction of the
// other; a real parameterisation is never this anisotropic, while at a pole the
// collapsed derivative is rounding noise (~1e-16 relative, ~1e-10 for a unit
// sphere placed 1e6 from the origin).
constexpr double kVanishingRatio = 1e-8;
// normal(): Su and Sv count as parallel when |Su x Sv| < kParallelSine |Su| |Sv|.
constexpr double kParallelSine = 1e-10;
// normal(): offsets into the domain tried last, as fractions of the domain size.
constexpr double kNormalOffsets[] = {1e-7, 1e-5, 1e-3};

std::string point_text(const Eigen::Vector3d& P) {
    return "(" + format_value(P.x()) + ", " + format_value(P.y()) + ", " +
           format_value(P.z()) + ")";
}

std::pair<double, double> knot_domain(const std::vector<double>& U, int p) {
    return {U[p], U[U.size() - p - 1]};
}

// Rows first .. end-1 of S with the u knot vector `knots` (which must fit them).
NurbsSurface rows_u(const NurbsSurface& S, int first, int end, std::vector<double> knots) {
    const int nv = S.count_v();
    const size_t b = static_cast<size_t>(first) * nv, e = static_cast<size_t>(end) * nv;
    std::vector<Eigen::Vector3d> points(S.points().begin() + b, S.points().begin() + e);
    std::vector<double> weights;
    if (S.is_rational()) weights.assign(S.weights().begin() + b, S.weights().begin() + e);
    return NurbsSurface(S.degree_u(), S.degree_v(), std::move(knots), S.knots_v(), end - first, nv,
                        std::move(points), std::move(weights));
}

// The part of S over u in [a, b], where a and b are u knots of multiplicity
// >= pu: rows la-pu .. fb-1 (la the last knot index at a, fb the first at b).
NurbsSurface extract_u(const NurbsSurface& S, double a, double b) {
    const auto& U = S.knots_u();
    const int p = S.degree_u();
    const int la = static_cast<int>(std::upper_bound(U.begin(), U.end(), a) - U.begin()) - 1;
    const int fb = static_cast<int>(std::lower_bound(U.begin(), U.end(), b) - U.begin());
    std::vector<double> knots(p + 1, a);
    knots.insert(knots.end(), U.begin() + la + 1, U.begin() + fb);
    knots.insert(knots.end(), p + 1, b);
    return rows_u(S, la - p, fb, std::move(knots));
}

// The rows of S that are non-zero somewhere on u in [a, b] (domain_u() contains
// [a, b]): spans ka (U[ka] <= a < U[ka+1]) to kb (U[kb] < b <= U[kb+1]) need rows
// ka-pu .. kb and knots ka-pu .. kb+pu+1 ([PT] Sec. 2.2, local support). The result
// equals S on [a, b] and is cheap to refine: knot insertion then touches only these rows.
NurbsSurface crop_u(const NurbsSurface& S, double a, double b) {
    const auto& U = S.knots_u();
    const int p = S.degree_u(), last = S.count_u() - 1;
    const int ka = std::clamp(static_cast<int>(std::upper_bound(U.begin(), U.end(), a) - U.begin()) - 1, p, last);
    const int kb = std::clamp(static_cast<int>(std::lower_bound(U.begin(), U.end(), b) - U.begin()) - 1, ka, last);
    if (ka == p && kb == last) return S;
    return rows_u(S, ka - p, kb + 1, std::vector<double>(U.begin() + (ka - p), U.begin() + (kb + p + 2)));
}

}  // namespace

NurbsSurface::NurbsSurface(int degree_u, int degree_v, std::vector<double> knots_u,
                           std::vector<double> knots_v, int nu, int nv,
                           std::vector<Eigen::Vector3d> points, std::vector<double> weights) {
    const std::string owner = "NurbsSurface";
    // Degrees first: nothing below allocates in proportion to them.
    for (int d : {degree_u, degree_v})
        if (d < 1 || d > kMaxDegree)
            throw InvalidInput(owner + ": degree " + std::to_string(d) + " in " +
                               (d == degree_u ? "u" : "v") + "; expected 1.." +
                               std::to_string(kMaxDegree) + " (kMaxDegree)");
    if (nu < 1 || nv < 1 ||
        static_cast<long long>(nu) * nv != static_cast<long long>(points.size()))
        throw InvalidInput(owner + ": " + std::to_string(points.size()) +
                           " control points for a grid of " + std::to_string(nu) + " x " +
                           std::to_string(nv) + "; expected nu * nv");
    if (!weights.empty() && weights.size() != points.size())
        throw InvalidInput(owner + ": " + std::to_string(weights.size()) + " weights for " +
                           std::to_string(points.size()) +
                           " control points; expected one weight per point, or none");
    validate_knot_vector(knots_u, degree_u, nu, owner + " (u knots)");
    validate_knot_vector(knots_v, degree_v, nv, owner + " (v knots)");
    for (size_t k = 0; k < points.size(); ++k)
        if (!points[k].allFinite())
            throw InvalidInput(owner + ": point[" + std::to_string(k) + "] (i = " +
                               std::to_string(k / nv) + ", j = " + std::to_string(k % nv) +
                               ") = " + point_text(points[k]) +
                               "; control points must be finite");
    const bool rational = validate_rational_weights(weights, owner);
    if (weights.empty()) weights.assign(points.size(), 1.0);
    pu_ = degree_u;
    pv_ = degree_v;
    U_ = std::move(knots_u);
    V_ = std::move(knots_v);
    nu_ = nu;
    nv_ = nv;
    P_ = std::move(points);
    w_ = std::move(weights);
    rational_ = rational;
}

bool NurbsSurface::is_affine() const {
    if (pu_ != 1 || pv_ != 1 || nu_ != 2 || nv_ != 2) return false;
    if (w_[1] != w_[0] || w_[2] != w_[0] || w_[3] != w_[0]) return false;
    const Eigen::Vector3d skew = P_[0] + P_[3] - P_[1] - P_[2];
    return skew.norm() <= 1e-12 * control_box().diagonal().norm();
}

std::pair<double, double> NurbsSurface::domain_u() const { return knot_domain(U_, pu_); }
std::pair<double, double> NurbsSurface::domain_v() const { return knot_domain(V_, pv_); }

// [PT] Algorithm A4.3 (A3.5 when not rational). (u, v) is clamped to the domain.
Eigen::Vector3d NurbsSurface::evaluate(double u, double v) const {
    const auto [u0, u1] = domain_u();
    const auto [v0, v1] = domain_v();
    u = std::min(std::max(u, u0), u1);
    v = std::min(std::max(v, v0), v1);
    const int su = knot_span(U_, pu_, u), sv = knot_span(V_, pv_, v);
    double Nu[kMaxDegree + 1], Nv[kMaxDegree + 1];
    basis_functions(U_, pu_, su, u, Nu);
    basis_functions(V_, pv_, sv, v, Nv);
    const int iu = su - pu_, iv = sv - pv_;
    Eigen::Vector3d S = Eigen::Vector3d::Zero();
    if (!rational_) {
        for (int k = 0; k <= pu_; ++k) {
            const Eigen::Vector3d* row = &P_[static_cast<size_t>(iu + k) * nv_ + iv];
            Eigen::Vector3d temp = Eigen::Vector3d::Zero();
            for (int l = 0; l <= pv_; ++l) temp += Nv[l] * row[l];
            S += Nu[k] * temp;
        }
        return S;
    }
    double W = 0.0;
    for (int k = 0; k <= pu_; ++k) {
        const size_t row = static_cast<size_t>(iu + k) * nv_ + iv;
        Eigen::Vector3d temp = Eigen::Vector3d::Zero();
        double wt = 0.0;
        for (int l = 0; l <= pv_; ++l) {
            const double c = Nv[l] * w_[row + l];
            temp += c * P_[row + l];
            wt += c;
        }
        S += Nu[k] * temp;
        W += Nu[k] * wt;
    }
    if (!(W > 0.0))
        throw NumericalFailure("NurbsSurface: rational denominator " + format_value(W) +
                               " at (u, v) = (" + format_value(u) + ", " + format_value(v) +
                               ")");
    return S / W;
}

// [PT] Algorithm A3.6 on homogeneous points (d = 2), then A4.4:
// S_kl = (A_kl - sum_j C(l,j) w_0j S_k,l-j - sum_i C(k,i) w_i0 S_k-i,l
//         - sum_i C(k,i) sum_j C(l,j) w_ij S_k-i,l-j) / w_00.
SurfaceDerivatives NurbsSurface::derivatives(double u, double v) const {
    constexpr int d = 2;
    const auto [u0, u1] = domain_u();
    const auto [v0, v1] = domain_v();
    u = std::min(std::max(u, u0), u1);
    v = std::min(std::max(v, v0), v1);
    const int su = knot_span(U_, pu_, u), sv = knot_span(V_, pv_, v);
    const int du = std::min(d, pu_), dv = std::min(d, pv_);
    double Nu[(d + 1) * (kMaxDegree + 1)], Nv[(d + 1) * (kMaxDegree + 1)];
    basis_function_derivatives(U_, pu_, su, u, du, Nu);
    basis_function_derivatives(V_, pv_, sv, v, dv, Nv);
    const int iu = su - pu_, iv = sv - pv_;

    Eigen::Vector3d A[d + 1][d + 1];
    double w[d + 1][d + 1];
    for (int k = 0; k <= d; ++k)
        for (int l = 0; l <= d; ++l) {
            A[k][l].setZero();
            w[k][l] = 0.0;
        }
    Eigen::Vector3d temp[kMaxDegree + 1];
    double wtemp[kMaxDegree + 1];
    for (int k = 0; k <= du; ++k) {
        for (int s = 0; s <= pv_; ++s) {
            temp[s].setZero();
            wtemp[s] = 0.0;
            for (int r = 0; r <= pu_; ++r) {
                const size_t idx = static_cast<size_t>(iu + r) * nv_ + iv + s;
                const double c = Nu[k * (pu_ + 1) + r] * w_[idx];
                temp[s] += c * P_[idx];
                wtemp[s] += c;
            }
        }
        for (int l = 0; l <= std::min(d - k, dv); ++l)
            for (int s = 0; s <= pv_; ++s) {
                A[k][l] += Nv[l * (pv_ + 1) + s] * temp[s];
                w[k][l] += Nv[l * (pv_ + 1) + s] * wtemp[s];
            }
    }
    if (!(w[0][0] > 0.0))
        throw NumericalFailure("NurbsSurface: rational denominator " + format_value(w[0][0]) +
                               " at (u, v) = (" + format_value(u) + ", " + format_value(v) +
                               ")");
    static constexpr double binom[d + 1][d + 1] = {{1, 0, 0}, {1, 1, 0}, {1, 2, 1}};
    Eigen::Vector3d SKL[d + 1][d + 1];
    for (int k = 0; k <= d; ++k)
        for (int l = 0; l <= d - k; ++l) {
            Eigen::Vector3d value = A[k][l];
            for (int j = 1; j <= l; ++j) value -= binom[l][j] * w[0][j] * SKL[k][l - j];
            for (int i = 1; i <= k; ++i) {
                value -= binom[k][i] * w[i][0] * SKL[k - i][l];
                Eigen::Vector3d inner = Eigen::Vector3d::Zero();
                for (int j = 1; j <= l; ++j) inner += binom[l][j] * w[i][j] * SKL[k - i][l - j];
                value -= binom[k][i] * inner;
            }
            SKL[k][l] = value / w[0][0];
        }
    return {SKL[0][0], SKL[1][0], SKL[0][1], SKL[2][0], SKL[1][1], SKL[0][2]};
}

// Su x Sv, normalised. At a degenerate point the normal is the limit from inside
// the domain: with Su = 0 (a collapsed u iso-curve, as at a sphere's pole),
// N(u, v+h) ~ h Suv x Sv, h pointing into the domain; symmetrically for Sv = 0.
// If that fails too (Su parallel to Sv, or a second-order degeneracy), Su x Sv
// at small diagonal offsets into the domain is used.
Eigen::Vector3d NurbsSurface::normal(double u, double v) const {
    auto regular = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                      Eigen::Vector3d& n) {
        const double la = a.norm(), lb = b.norm();
        if (!(std::min(la, lb) > kVanishingRatio * std::max(la, lb))) return false;
        n = a.cross(b);
        const double ln = n.norm();
        if (!(ln > kParallelSine * la * lb)) return false;
        n /= ln;
        return true;
    };
    const SurfaceDerivatives D = derivatives(u, v);
    Eigen::Vector3d n;
    if (regular(D.Su, D.Sv, n)) return n;

    const auto [u0, u1] = domain_u();
    const auto [v0, v1] = domain_v();
    // Direction into the domain: +1 from the lower half, -1 from the upper.
    const double hu = (u < 0.5 * (u0 + u1)) ? 1.0 : -1.0;
    const double hv = (v < 0.5 * (v0 + v1)) ? 1.0 : -1.0;
    const double lu = D.Su.norm(), lv = D.Sv.norm();
    if (lu <= kVanishingRatio * lv && regular(D.Suv, D.Sv, n)) return hv * n;
    if (lv <= kVanishingRatio * lu && regular(D.Su, D.Suv, n)) return hu * n;
    for (double fraction : kNormalOffsets) {
        const SurfaceDerivatives E =
            derivatives(u + hu * fraction * (u1 - u0), v + hv * fraction * (v1 - v0));
        if (regular(E.Su, E.Sv, n)) return n;
    }
    throw NumericalFailure("NurbsSurface: no normal direction at (u, v) = (" +
                           format_value(u) + ", " + format_value(v) +
                           "): Su x Sv vanishes there and nearby");
}

// [PT] Algorithm A5.3: the plan of A5.1 (geom/knot_insertion.h), worked out once from
// the u knots, applied to each column j of the grid.
NurbsSurface NurbsSurface::insert_knot_u(double u, int times) const {
    const KnotInsertion plan = plan_knot_insertion(U_, pu_, u, times, "NurbsSurface::insert_knot_u");
    if (plan.r == 0) return *this;
    const int nu = nu_ + plan.r;
    std::vector<Eigen::Vector4d> grid(static_cast<size_t>(nu) * nv_);
    for (int j = 0; j < nv_; ++j) {
        const std::vector<Eigen::Vector4d> column = geom::insert_knot(plan, homogeneous_column(j));
        for (int i = 0; i < nu; ++i) grid[static_cast<size_t>(i) * nv_ + j] = column[i];
    }
    return from_homogeneous(pu_, pv_, plan.knots, V_, nu, nv_, grid, rational_);
}

NurbsSurface NurbsSurface::insert_knot_v(double v, int times) const {
    return swapped_uv().insert_knot_u(v, times).swapped_uv();
}

std::vector<Eigen::Vector4d> NurbsSurface::homogeneous_column(int j) const {
    std::vector<Eigen::Vector4d> column(nu_);
    for (int i = 0; i < nu_; ++i) {
        const size_t idx = static_cast<size_t>(i) * nv_ + j;
        column[i] = homogeneous<3>(P_[idx], w_[idx]);
    }
    return column;
}

NurbsSurface NurbsSurface::from_homogeneous(int pu, int pv, std::vector<double> U,
                                            std::vector<double> V, int nu, int nv,
                                            const std::vector<Eigen::Vector4d>& grid, bool rational) {
    NurbsSurface result;
    result.pu_ = pu;
    result.pv_ = pv;
    result.U_ = std::move(U);
    result.V_ = std::move(V);
    result.nu_ = nu;
    result.nv_ = nv;
    result.rational_ = rational;
    result.P_.resize(grid.size());
    result.w_.resize(grid.size());
    for (size_t i = 0; i < grid.size(); ++i) {
        result.w_[i] = rational ? grid[i][3] : 1.0;
        result.P_[i] = euclidean<3>(grid[i], rational);
    }
    return result;
}

// [PT] Algorithm A5.6 on each column (u pieces), then on each row of the result (v
// pieces): O(nu nv (pu^2 + pv^2)), where inserting every knot in turn copied the whole
// grid once per knot.
std::vector<NurbsSurface> NurbsSurface::bezier_patches() const {
    const char* owner = "NurbsSurface::bezier_patches";
    const DomainClamp clamp_u = plan_domain_clamp(U_, pu_, owner), clamp_v = plan_domain_clamp(V_, pv_, owner);
    const size_t wu = static_cast<size_t>(pu_) + 1, wv = static_cast<size_t>(pv_) + 1;
    const std::vector<double>& bu = clamp_u.breaks;
    const std::vector<double>& bv = clamp_v.breaks;
    // pieces_u[j]: column j cut at the u breaks (rows piece-major).
    std::vector<std::vector<Eigen::Vector4d>> pieces_u(nv_);
    for (int j = 0; j < nv_; ++j) pieces_u[j] = bezier_pieces(clamp_u, pu_, homogeneous_column(j));
    const size_t rows = pieces_u[0].size();
    // grid[row][v piece point]: each row of the u-cut grid cut at the v breaks.
    std::vector<std::vector<Eigen::Vector4d>> grid(rows);
    for (size_t row = 0; row < rows; ++row) {
        std::vector<Eigen::Vector4d> line(nv_);
        for (int j = 0; j < nv_; ++j) line[j] = pieces_u[j][row];
        grid[row] = bezier_pieces(clamp_v, pv_, std::move(line));
    }
    std::vector<NurbsSurface> patches;
    patches.reserve((bu.size() - 1) * (bv.size() - 1));
    for (size_t a = 0; a + 1 < bu.size(); ++a)
        for (size_t b = 0; b + 1 < bv.size(); ++b) {
            std::vector<Eigen::Vector4d> H(wu * wv);
            for (size_t i = 0; i < wu; ++i)
                for (size_t j = 0; j < wv; ++j) H[i * wv + j] = grid[a * wu + i][b * wv + j];
            patches.push_back(from_homogeneous(pu_, pv_, bezier_knots(pu_, bu[a], bu[a + 1]),
                                               bezier_knots(pv_, bv[b], bv[b + 1]), static_cast<int>(wu),
                                               static_cast<int>(wv), H, rational_));
        }
    return patches;
}

NurbsSurface NurbsSurface::sub_surface(double u0, double u1, double v0, double v1) const {
    NurbsSurface S = *this;
    for (int pass = 0; pass < 2; ++pass) {
        // Pass 0 cuts u in S; pass 1 cuts v in the swapped S.
        const double a_in = pass == 0 ? u0 : v0, b_in = pass == 0 ? u1 : v1;
        const auto [lo, hi] = S.domain_u();
        const double tol = kKnotTolerance * (hi - lo);
        if (!(a_in < b_in) || a_in < lo - tol || b_in > hi + tol)
            throw InvalidInput(std::string("NurbsSurface::sub_surface: ") +
                               (pass == 0 ? "u" : "v") + " range [" + format_value(a_in) +
                               ", " + format_value(b_in) + "]; expected a < b inside [" +
                               format_value(lo) + ", " + format_value(hi) + "]");
        const double a = snap_to_knot(S.knots_u(), std::max(a_in, lo), tol);
        const double b = snap_to_knot(S.knots_u(), std::min(b_in, hi), tol);
        if (!(a < b))
            throw InvalidInput("NurbsSurface::sub_surface: range [" + format_value(a_in) +
                               ", " + format_value(b_in) + "] shorter than the knot tolerance");
        const NurbsSurface local = crop_u(S, a, b);
        S = extract_u(local.insert_knot_u(a, S.degree_u()).insert_knot_u(b, S.degree_u()), a, b)
                .swapped_uv();
    }
    return S;
}

NurbsSurface NurbsSurface::swapped_uv() const {
    NurbsSurface result;
    result.pu_ = pv_;
    result.pv_ = pu_;
    result.U_ = V_;
    result.V_ = U_;
    result.nu_ = nv_;
    result.nv_ = nu_;
    result.rational_ = rational_;
    result.P_.resize(P_.size());
    result.w_.resize(w_.size());
    for (int i = 0; i < nu_; ++i)
        for (int j = 0; j < nv_; ++j) {
            result.P_[static_cast<size_t>(j) * nu_ + i] = P_[static_cast<size_t>(i) * nv_ + j];
            result.w_[static_cast<size_t>(j) * nu_ + i] = w_[static_cast<size_t>(i) * nv_ + j];
        }
    return result;
}

Eigen::AlignedBox3d NurbsSurface::control_box() const {
    Eigen::AlignedBox3d box;
    for (const Eigen::Vector3d& P : P_) box.extend(P);
    return box;
}

NurbsSurface NurbsSurface::transformed(const Eigen::Affine3d& T) const {
    NurbsSurface result = *this;
    for (Eigen::Vector3d& P : result.P_) P = T * P;
    return result;
}

}  // namespace trimkit::geom
