#include "tess/surface_evaluator.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "geom/bspline_basis.h"
#include "geom/error.h"

namespace trimkit::tess {

SurfaceEvaluator::SurfaceEvaluator(const geom::NurbsSurface& surface)
    : surface_(surface), p_(surface.degree_u()), q_(surface.degree_v()) {
    std::tie(u_lo_, u_hi_) = surface.domain_u();
    std::tie(v_lo_, v_hi_) = surface.domain_v();
    Nv_.resize(2 * (q_ + 1));
    Nu_.resize(2 * (p_ + 1));
    inner_.resize(p_ + 1);
    inner_dv_.resize(p_ + 1);
}

void SurfaceEvaluator::evaluate(double u, double v, Eigen::Vector3d& S, Eigen::Vector3d& Su,
                                Eigen::Vector3d& Sv) {
    u = std::clamp(u, u_lo_, u_hi_);
    v = std::clamp(v, v_lo_, v_hi_);
    const auto& U = surface_.knots_u();
    const auto& V = surface_.knots_v();
    if (sv_ < 0 || v != v_) {
        v_ = v;
        sv_ = geom::knot_span(V, q_, v);
        geom::basis_function_derivatives(V, q_, sv_, v, 1, Nv_.data());
        su_ = -1;  // inner sums depend on v
    }
    const int su = geom::knot_span(U, p_, u);
    if (su != su_) {
        su_ = su;
        const bool rational = surface_.is_rational();
        for (int k = 0; k <= p_; ++k) {
            Eigen::Vector4d a = Eigen::Vector4d::Zero(), b = Eigen::Vector4d::Zero();
            for (int l = 0; l <= q_; ++l) {
                const int i = su - p_ + k, j = sv_ - q_ + l;
                const double w = rational ? surface_.weight(i, j) : 1.0;
                Eigen::Vector4d Pw;
                Pw << w * surface_.point(i, j), w;
                a += Nv_[l] * Pw;
                b += Nv_[q_ + 1 + l] * Pw;
            }
            inner_[k] = a;
            inner_dv_[k] = b;
        }
    }
    geom::basis_function_derivatives(U, p_, su, u, 1, Nu_.data());
    Eigen::Vector4d H = Eigen::Vector4d::Zero(), Hu = H, Hv = H;
    for (int k = 0; k <= p_; ++k) {
        H += Nu_[k] * inner_[k];
        Hu += Nu_[p_ + 1 + k] * inner_[k];
        Hv += Nu_[k] * inner_dv_[k];
    }
    if (!(std::abs(H[3]) > 0.0))
        throw geom::NumericalFailure("surface evaluation: rational denominator vanishes at (" +
                                     geom::format_value(u) + ", " + geom::format_value(v) + ")");
    S = H.head<3>() / H[3];
    Su = (Hu.head<3>() - Hu[3] * S) / H[3];
    Sv = (Hv.head<3>() - Hv[3] * S) / H[3];
}

Eigen::Vector3d SurfaceEvaluator::normal(double u, double v, const Eigen::Vector3d& Su,
                                         const Eigen::Vector3d& Sv) const {
    // Below this sine of the angle between Su and Sv (or with a vanishing
    // derivative) the cross product is noise: a pole or a collapsed edge.
    constexpr double kDegenerateSine = 1e-10;
    const Eigen::Vector3d n = Su.cross(Sv);
    const double len = n.norm();
    if (len > kDegenerateSine * Su.norm() * Sv.norm() && len > 0.0 && std::isfinite(len))
        return n / len;
    return surface_.normal(u, v);
}

}  // namespace trimkit::tess
