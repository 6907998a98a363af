// Direct evaluation of S, Su and Sv that reuses basis functions between
// consecutive calls [Balazs] Sec. 8: the v basis functions when v is unchanged,
// and the inner sums of eq. (1) when the u span is unchanged too. Callers sort
// their points by (v, u) to benefit. Parameters outside the domain are clamped.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "geom/nurbs_surface.h"

namespace trimkit::tess {

class SurfaceEvaluator {
public:
    explicit SurfaceEvaluator(const geom::NurbsSurface& surface);

    // S(u,v) and its first partial derivatives. Throws geom::NumericalFailure if the
    // rational denominator vanishes.
    void evaluate(double u, double v, Eigen::Vector3d& S, Eigen::Vector3d& Su,
                  Eigen::Vector3d& Sv);
    // Unit normal Su x Sv at (u,v) (not flipped for face orientation); at degenerate
    // points (poles) falls back to NurbsSurface::normal.
    Eigen::Vector3d normal(double u, double v, const Eigen::Vector3d& Su,
                           const Eigen::Vector3d& Sv) const;

private:
    const geom::NurbsSurface& surface_;
    int p_, q_;
    double u_lo_, u_hi_, v_lo_, v_hi_;
    // Cached v basis (values, first derivatives) at v_, span sv_.
    double v_ = 0.0;
    int sv_ = -1;
    std::vector<double> Nv_;  // 2 x (q+1)
    // Cached inner sums for u span su_: rows i = su-p..su of sum_j Nv_j Pw_ij and
    // sum_j Nv'_j Pw_ij (homogeneous).
    int su_ = -1;
    std::vector<Eigen::Vector4d> inner_, inner_dv_;
    std::vector<double> Nu_;  // 2 x (p+1)
};

}  // namespace trimkit::tess
