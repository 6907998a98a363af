#include "tess/bilinear_error.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Geometry>

#include "tess/second_derivative_bound.h"

namespace trimkit::tess {
namespace {

// Splits closer than this to a patch side make slivers without reducing the error.
constexpr double kMinSplit = 0.1;
// Weights equal to this relative spread make a patch polynomial (control net bound).
constexpr double kPolynomialWeightSpread = 1e-14;
// Plans for more pieces than this are not trusted (the bound of a large patch
// overestimates, so a planned cut would land off the final grid): halve instead.
constexpr double kMaxPlannedPieces = 8.0;

bool is_rational(const BezierPatch& patch) {
    double w_min = patch.Pw[0][3], w_max = w_min;
    for (const Eigen::Vector4d& P : patch.Pw) w_min = std::min(w_min, P[3]), w_max = std::max(w_max, P[3]);
    return w_max - w_min > kPolynomialWeightSpread * std::abs(w_max);
}

// Rational patch, kGuaranteed: second_derivative_bound and its split.
BilinearError rational_error(const BezierPatch& patch, double tolerance) {
    const SecondDerivativeBound M = second_derivative_bound(patch);
    BilinearError result;
    result.bound = M.error();
    if (!std::isfinite(result.bound)) {
        result.bound = std::numeric_limits<double>::infinity();
        return result;
    }
    result.derivatives = M;
    // Halving s divides the M_uu term by 4 and the M_uv term by 2: cut across the
    // larger of M_uu, M_vv (ties: the longer side in 3D, by the control polygon).
    result.split_in_u = M.M_uu > M.M_vv ||
                        (M.M_uu == M.M_vv && (patch.euclidean(patch.p, 0) - patch.euclidean(0, 0)).norm() >=
                                                 (patch.euclidean(0, patch.q) - patch.euclidean(0, 0)).norm());
    result.split = 0.5;
    const double own = (result.split_in_u ? M.M_uu : M.M_vv) / 8.0;
    const double rest = result.bound - own;
    if (tolerance > rest && own > 0.0) {
        // k pieces across: own / k^2 + rest <= tolerance.
        const double k = std::ceil(std::sqrt(own / (tolerance - rest)));
        if (k >= 3.0 && k <= kMaxPlannedPieces) result.split = std::floor(k / 2.0) / k;
    }
    return result;
}

// second_derivative_bound of a polynomial patch, from its hodographs' control points:
// |S_ss| <= m (m - 1) max |P_{i+2,j} - 2 P_{i+1,j} + P_ij|, |S_st| <= m n max |twist of
// P|, |S_tt| likewise (the convex hull of a Bezier derivative's control points).
SecondDerivativeBound polynomial_derivative_bound(const BezierPatch& patch) {
    const int m = patch.p, n = patch.q;
    SecondDerivativeBound M;
    for (int i = 0; i <= m; ++i)
        for (int j = 0; j <= n; ++j) {
            const Eigen::Vector3d P = patch.euclidean(i, j);
            if (i + 2 <= m)
                M.M_uu = std::max(M.M_uu, (patch.euclidean(i + 2, j) - 2.0 * patch.euclidean(i + 1, j) + P).norm());
            if (j + 2 <= n)
                M.M_vv = std::max(M.M_vv, (patch.euclidean(i, j + 2) - 2.0 * patch.euclidean(i, j + 1) + P).norm());
            if (i + 1 <= m && j + 1 <= n)
                M.M_uv = std::max(M.M_uv, (patch.euclidean(i + 1, j + 1) - patch.euclidean(i + 1, j) -
                                           patch.euclidean(i, j + 1) + P).norm());
        }
    M.M_uu *= m * (m - 1);
    M.M_vv *= n * (n - 1);
    M.M_uv *= m * n;
    return M;
}

// Largest distance between two of the points (squared norms compared exactly, so the
// same value as over all pairs). A point whose farthest corner of the points' box is no
// farther than the largest distance found so far has no pair beyond it and is skipped:
// high-degree nets (BUC50025.igs: degree 12 x 12, 169 points) are mostly such points.
double diameter(const Eigen::Vector3d* D, int count) {
    Eigen::AlignedBox3d box;
    int extreme[6] = {0, 0, 0, 0, 0, 0};  // lowest and highest point per axis
    for (int a = 0; a < count; ++a) {
        box.extend(D[a]);
        for (int k = 0; k < 3; ++k) {
            if (D[a][k] < D[extreme[2 * k]][k]) extreme[2 * k] = a;
            if (D[a][k] > D[extreme[2 * k + 1]][k]) extreme[2 * k + 1] = a;
        }
    }
    double best = 0.0;
    for (int a : extreme)
        for (int b : extreme) best = std::max(best, (D[a] - D[b]).squaredNorm());
    for (int a = 0; a < count; ++a) {
        const Eigen::Vector3d far = (D[a] - box.min()).cwiseAbs().cwiseMax((box.max() - D[a]).cwiseAbs());
        if (far.squaredNorm() <= best) continue;
        for (int b = a + 1; b < count; ++b) best = std::max(best, (D[a] - D[b]).squaredNorm());
    }
    return std::sqrt(best);
}

}  // namespace

BilinearError bilinear_error(const BezierPatch& patch, ErrorMode mode, double tolerance) {
    if (mode == ErrorMode::kGuaranteed && is_rational(patch)) return rational_error(patch, tolerance);
    const int m = patch.p, n = patch.q;
    Eigen::Vector3d P[(geom::kMaxDegree + 1) * (geom::kMaxDegree + 1)];
    auto at = [&](int i, int j) -> Eigen::Vector3d& { return P[i * (n + 1) + j]; };
    for (int i = 0; i <= m; ++i)
        for (int j = 0; j <= n; ++j) {
            at(i, j) = mode == ErrorMode::kApproximate
                           ? patch.evaluate(static_cast<double>(i) / m, static_cast<double>(j) / n)
                           : patch.euclidean(i, j);
        }
    const Eigen::Vector3d C00 = at(0, 0), Cm0 = at(m, 0), C0n = at(0, n), Cmn = at(m, n);
    const Eigen::Vector3d e_u = Cm0 - C00, e_v = C0n - C00, d = C00 - Cm0 - C0n + Cmn;

    // D_ij = P_ij - S~(i/m, j/n); S~(a,b) = C00 + a e_u + b e_v + a b d (re-derived).
    Eigen::Vector3d D[(geom::kMaxDegree + 1) * (geom::kMaxDegree + 1)];
    double max_d = -1.0, dev_u = 0.0, dev_v = 0.0;
    int k = 0, l = 0;
    for (int i = 0; i <= m; ++i)
        for (int j = 0; j <= n; ++j) {
            const double a = static_cast<double>(i) / m, b = static_cast<double>(j) / n;
            const Eigen::Vector3d Dij = at(i, j) - (C00 + a * e_u + b * e_v + a * b * d);
            D[i * (n + 1) + j] = Dij;
            const double len = Dij.norm();
            if (len > max_d) max_d = len, k = i, l = j;
            // Deviation from the chords along u (row j) and along v (column i).
            dev_u = std::max(dev_u, (at(i, j) - ((1 - a) * at(0, j) + a * at(m, j))).norm());
            dev_v = std::max(dev_v, (at(i, j) - ((1 - b) * at(i, 0) + b * at(i, n))).norm());
        }
    const double twist = 0.25 * d.norm();

    BilinearError result;
    if (mode == ErrorMode::kApproximate) {
        result.bound = max_d + twist;
    } else {
        result.bound = diameter(D, (m + 1) * (n + 1)) + twist;
    }
    if (!std::isfinite(result.bound)) result.bound = std::numeric_limits<double>::infinity();

    // Split at the control point of largest bilinear error [Balazs] Sec. 5.2, in the
    // direction whose chords it deviates from most (departure: the paper compares the
    // 3D distance of S(k/m, l/n) to the two split lines; this picks the same direction
    // on cylinders and needs no extra evaluation).
    const bool interior_u = k > 0 && k < m, interior_v = l > 0 && l < n;
    if (twist >= max_d || (!interior_u && !interior_v)) {
        // Twist-dominated (or bilinear-exact) patch: halve the longer direction.
        const double len_u = e_u.norm() + (Cmn - C0n).norm();
        const double len_v = e_v.norm() + (Cmn - Cm0).norm();
        result.split_in_u = len_u >= len_v;
        result.split = 0.5;
    } else if (interior_u && (!interior_v || dev_u >= dev_v)) {
        result.split_in_u = true;
        result.split = static_cast<double>(k) / m;
    } else {
        result.split_in_u = false;
        result.split = static_cast<double>(l) / n;
    }
    result.split = std::clamp(result.split, kMinSplit, 1.0 - kMinSplit);
    // Both bound a polynomial patch; the control net's lags behind on high degrees.
    if (mode == ErrorMode::kGuaranteed && result.bound > tolerance)
        result.bound = std::min(result.bound, polynomial_derivative_bound(patch).error());
    return result;
}

}  // namespace trimkit::tess
