// Hodograph bounds per Bézier patch / segment, combined by the quotient rule for
// rational objects (see derivative_bounds.h).
#include "tess/derivative_bounds.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "geom/knot_vector.h"

namespace trimkit::tess {

namespace {

// Homogeneous point w·(P - O), w.
using Vector4 = Eigen::Vector4d;

double xyz_norm(const Vector4& h) { return h.head<3>().norm(); }

}  // namespace

SurfaceDerivativeBounds surface_derivative_bounds(const geom::NurbsSurface& S) {
    const Eigen::Vector3d O = S.control_box().center();
    SurfaceDerivativeBounds M;
    for (const geom::NurbsSurface& patch : S.bezier_patches()) {
        const int p = patch.degree_u(), q = patch.degree_v();
        const auto [u0, u1] = patch.domain_u();
        const auto [v0, v1] = patch.domain_v();
        const double du = u1 - u0, dv = v1 - v0;
        auto H = [&](int i, int j) {
            const double w = patch.weight(i, j);
            Vector4 h;
            h << w * (patch.point(i, j) - O), w;
            return h;
        };
        double w_min = INFINITY, R = 0.0;
        for (int i = 0; i <= p; ++i)
            for (int j = 0; j <= q; ++j) {
                w_min = std::min(w_min, patch.weight(i, j));
                R = std::max(R, (patch.point(i, j) - O).norm());
            }
        // Maxima over the hodograph control points: A = |xyz part|, W = |w part|.
        double Au = 0, Av = 0, Auu = 0, Auv = 0, Avv = 0;
        double Wu = 0, Wv = 0, Wuu = 0, Wuv = 0, Wvv = 0;
        for (int i = 0; i <= p; ++i)
            for (int j = 0; j <= q; ++j) {
                if (i < p) {
                    const Vector4 d = (p / du) * (H(i + 1, j) - H(i, j));
                    Au = std::max(Au, xyz_norm(d));
                    Wu = std::max(Wu, std::abs(d.w()));
                }
                if (j < q) {
                    const Vector4 d = (q / dv) * (H(i, j + 1) - H(i, j));
                    Av = std::max(Av, xyz_norm(d));
                    Wv = std::max(Wv, std::abs(d.w()));
                }
                if (i + 1 < p) {
                    const Vector4 d =
                        (p * (p - 1) / (du * du)) * (H(i + 2, j) - 2.0 * H(i + 1, j) + H(i, j));
                    Auu = std::max(Auu, xyz_norm(d));
                    Wuu = std::max(Wuu, std::abs(d.w()));
                }
                if (j + 1 < q) {
                    const Vector4 d =
                        (q * (q - 1) / (dv * dv)) * (H(i, j + 2) - 2.0 * H(i, j + 1) + H(i, j));
                    Avv = std::max(Avv, xyz_norm(d));
                    Wvv = std::max(Wvv, std::abs(d.w()));
                }
                if (i < p && j < q) {
                    const Vector4 d = (p * q / (du * dv)) *
                                      (H(i + 1, j + 1) - H(i + 1, j) - H(i, j + 1) + H(i, j));
                    Auv = std::max(Auv, xyz_norm(d));
                    Wuv = std::max(Wuv, std::abs(d.w()));
                }
            }
        const double Mu = (Au + R * Wu) / w_min, Mv = (Av + R * Wv) / w_min;
        M.Mu = std::max(M.Mu, Mu);
        M.Mv = std::max(M.Mv, Mv);
        M.Muu = std::max(M.Muu, (Auu + 2.0 * Mu * Wu + R * Wuu) / w_min);
        M.Mvv = std::max(M.Mvv, (Avv + 2.0 * Mv * Wv + R * Wvv) / w_min);
        M.Muv = std::max(M.Muv, (Auv + Mu * Wv + Mv * Wu + R * Wuv) / w_min);
    }
    return M;
}

SurfaceDerivativeBounds surface_derivative_bounds(const geom::NurbsSurface& S,
                                                  const Eigen::AlignedBox2d& region) {
    const std::pair<double, double> dom[2] = {S.domain_u(), S.domain_v()};
    double lo[2], hi[2];
    bool whole = true;
    for (int d = 0; d < 2; ++d) {
        const auto [a, b] = dom[d];
        const double min_width = kMinRegionRelative * (b - a);
        lo[d] = std::clamp(region.min()(d), a, b);
        hi[d] = std::clamp(region.max()(d), a, b);
        if (hi[d] - lo[d] < min_width) {
            const double m = 0.5 * (lo[d] + hi[d]);
            lo[d] = std::max(a, m - min_width);
            hi[d] = std::min(b, m + min_width);
        }
        whole = whole && lo[d] <= a && hi[d] >= b;
    }
    if (whole) return surface_derivative_bounds(S);
    return surface_derivative_bounds(S.sub_surface(lo[0], hi[0], lo[1], hi[1]));
}

bool is_c1_inside(const geom::NurbsSurface& S, const Eigen::AlignedBox2d& region) {
    const std::vector<double>* knots[2] = {&S.knots_u(), &S.knots_v()};
    const int degree[2] = {S.degree_u(), S.degree_v()};
    for (int d = 0; d < 2; ++d) {
        const std::vector<double>& U = *knots[d];
        const double tol = geom::kKnotTolerance * (U.back() - U.front());
        const double lo = region.min()(d) + tol, hi = region.max()(d) - tol;
        for (size_t i = 0; i < U.size();) {
            size_t j = i;
            while (j < U.size() && U[j] - U[i] <= tol) ++j;
            const int m = static_cast<int>(j - i);
            if (U[i] > lo && U[i] < hi && m >= degree[d]) return false;
            i = j;
        }
    }
    return true;
}

CurveDerivativeBounds curve_derivative_bounds(const geom::NurbsCurve2d& c) {
    const Eigen::Vector2d O = c.control_box().center();
    CurveDerivativeBounds M;
    for (const geom::NurbsCurve2d& seg : c.bezier_segments()) {
        const int p = seg.degree();
        const auto [t0, t1] = seg.domain();
        const double dt = t1 - t0;
        std::vector<Eigen::Vector3d> H(p + 1);  // (w (u - Ou), w (v - Ov), w)
        double w_min = INFINITY;
        Eigen::Vector2d R = Eigen::Vector2d::Zero();  // per component
        double R_norm = 0.0;
        for (int i = 0; i <= p; ++i) {
            const double w = seg.weights()[i];
            const Eigen::Vector2d d = seg.points()[i] - O;
            H[i] << w * d, w;
            w_min = std::min(w_min, w);
            R = R.cwiseMax(d.cwiseAbs());
            R_norm = std::max(R_norm, d.norm());
        }
        Eigen::Vector2d A1 = Eigen::Vector2d::Zero();  // per component of H'
        double A1_norm = 0, A2_norm = 0, W1 = 0, W2 = 0;
        for (int i = 0; i < p; ++i) {
            const Eigen::Vector3d d = (p / dt) * (H[i + 1] - H[i]);
            A1 = A1.cwiseMax(d.head<2>().cwiseAbs());
            A1_norm = std::max(A1_norm, d.head<2>().norm());
            W1 = std::max(W1, std::abs(d.z()));
        }
        for (int i = 0; i + 1 < p; ++i) {
            const Eigen::Vector3d d = (p * (p - 1) / (dt * dt)) * (H[i + 2] - 2.0 * H[i + 1] + H[i]);
            A2_norm = std::max(A2_norm, d.head<2>().norm());
            W2 = std::max(W2, std::abs(d.z()));
        }
        const double M1 = (A1_norm + R_norm * W1) / w_min;  // sup |c'|
        M.Mtu = std::max(M.Mtu, (A1.x() + R.x() * W1) / w_min);
        M.Mtv = std::max(M.Mtv, (A1.y() + R.y() * W1) / w_min);
        M.Mtt = std::max(M.Mtt, (A2_norm + 2.0 * M1 * W1 + R_norm * W2) / w_min);
    }
    return M;
}

}  // namespace trimkit::tess
