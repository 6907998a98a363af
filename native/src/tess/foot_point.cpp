#include "tess/foot_point.h"

#include <algorithm>
#include <limits>

#include "geom/error.h"

namespace trimkit::tess {

Eigen::Vector2d foot_point(const geom::NurbsSurface& surface, const Eigen::Vector3d& x,
                           const Eigen::Vector2d& start) {
    const auto [u0, u1] = surface.domain_u();
    const auto [v0, v1] = surface.domain_v();
    Eigen::Vector2d uv(std::clamp(start.x(), u0, u1), std::clamp(start.y(), v0, v1));
    geom::SurfaceDerivatives d = surface.derivatives(uv.x(), uv.y());
    double dist = (d.S - x).squaredNorm();
    for (int it = 0; it < kFootPointIterations; ++it) {
        // Gradient and Hessian of |S - x|² / 2 ([PT] eq. 6.6, 6.7).
        const Eigen::Vector3d r = d.S - x;
        const Eigen::Vector2d g(d.Su.dot(r), d.Sv.dot(r));
        Eigen::Matrix2d J;
        J << d.Su.squaredNorm() + r.dot(d.Suu), d.Su.dot(d.Sv) + r.dot(d.Suv),
            d.Su.dot(d.Sv) + r.dot(d.Suv), d.Sv.squaredNorm() + r.dot(d.Svv);
        // Levenberg-style damping keeps the step finite at poles and folds.
        const double damp = 1e-12 * (J.diagonal().cwiseAbs().maxCoeff() + 1e-300);
        J(0, 0) += damp;
        J(1, 1) += damp;
        Eigen::Vector2d step = J.fullPivLu().solve(-g);
        if (!step.allFinite()) break;
        // Departure from [PT]: backtracking, so every accepted step lowers |S - x|
        // (plain Newton can stall or wander at poles and saddles).
        bool accepted = false;
        Eigen::Vector2d next;
        geom::SurfaceDerivatives dn;
        for (int halving = 0; halving < kFootPointHalvings && !accepted; ++halving, step *= 0.5) {
            next = {std::clamp(uv.x() + step.x(), u0, u1), std::clamp(uv.y() + step.y(), v0, v1)};
            try {
                dn = surface.derivatives(next.x(), next.y());
            } catch (const geom::NumericalFailure&) {
                continue;
            }
            accepted = (dn.S - x).squaredNorm() <= dist;
        }
        if (!accepted) break;
        const Eigen::Vector2d moved = next - uv;
        const double size = d.Su.norm() * (u1 - u0) + d.Sv.norm() * (v1 - v0);
        uv = next;
        d = dn;
        dist = (d.S - x).squaredNorm();
        if ((d.Su * moved.x() + d.Sv * moved.y()).norm() <= kFootPointStep * size) break;
    }
    return uv;
}

}  // namespace trimkit::tess
