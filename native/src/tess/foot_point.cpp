#include "tess/foot_point.h"

#include <algorithm>
#include <limits>

#include <Eigen/Cholesky>

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
        Eigen::Matrix2d G;  // Gauss-Newton part, positive semi-definite
        G << d.Su.squaredNorm(), d.Su.dot(d.Sv), d.Su.dot(d.Sv), d.Sv.squaredNorm();
        Eigen::Matrix2d J = G;
        J(0, 0) += r.dot(d.Suu);
        J(0, 1) += r.dot(d.Suv);
        J(1, 0) += r.dot(d.Suv);
        J(1, 1) += r.dot(d.Svv);
        // Levenberg-style damping keeps the step finite at poles and folds.
        const double damp = kFootPointDamping * (G.trace() + 1e-300);
        // Departure from [PT]: where the full Hessian is not positive definite (far
        // from the surface, near a fold or a ridge of |S - x|) its Newton step need
        // not go downhill; the Gauss-Newton step always does.
        const bool convex = J(0, 0) > 0.0 && J.determinant() > 0.0;
        Eigen::Matrix2d H = convex ? J : G;
        H(0, 0) += damp;
        H(1, 1) += damp;
        Eigen::Vector2d step = H.ldlt().solve(-g);
        if (!step.allFinite() || !(step.dot(g) < 0.0)) {
            if (!convex) break;
            H = G;
            H(0, 0) += damp;
            H(1, 1) += damp;
            step = H.ldlt().solve(-g);
            if (!step.allFinite() || !(step.dot(g) < 0.0)) break;
        }
        // Departure from [PT]: backtracking, so every accepted step lowers |S - x|
        // (plain Newton can stall or wander at poles and saddles).
        bool accepted = false;
        Eigen::Vector2d next;
        geom::SurfaceDerivatives dn;
        for (int halving = 0; halving < kFootPointHalvings && !accepted; ++halving, step *= 0.5) {
            next = {std::clamp(uv.x() + step.x(), u0, u1), std::clamp(uv.y() + step.y(), v0, v1)};
            if (next == uv) break;
            try {
                dn = surface.derivatives(next.x(), next.y());
            } catch (const geom::NumericalFailure&) {
                continue;
            }
            accepted = (dn.S - x).squaredNorm() < dist;
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
