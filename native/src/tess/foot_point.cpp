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
    Eigen::Vector2d best = uv;
    double best_d = std::numeric_limits<double>::infinity();
    for (int it = 0; it <= kFootPointIterations; ++it) {
        geom::SurfaceDerivatives d;
        try {
            d = surface.derivatives(uv.x(), uv.y());
        } catch (const geom::NumericalFailure&) {
            if (it == 0) throw;
            break;
        }
        const Eigen::Vector3d r = d.S - x;
        const double dist = r.squaredNorm();
        if (dist < best_d) {
            best_d = dist;
            best = uv;
        }
        if (it == kFootPointIterations) break;
        // Gradient and Hessian of |S - x|² / 2 ([PT] eq. 6.6, 6.7).
        const Eigen::Vector2d g(d.Su.dot(r), d.Sv.dot(r));
        Eigen::Matrix2d J;
        J << d.Su.squaredNorm() + r.dot(d.Suu), d.Su.dot(d.Sv) + r.dot(d.Suv),
            d.Su.dot(d.Sv) + r.dot(d.Suv), d.Sv.squaredNorm() + r.dot(d.Svv);
        const double damp = 1e-12 * (J.diagonal().cwiseAbs().maxCoeff() + 1e-300);
        J(0, 0) += damp;
        J(1, 1) += damp;
        const Eigen::Vector2d step = J.fullPivLu().solve(-g);
        if (!step.allFinite()) break;
        Eigen::Vector2d next(std::clamp(uv.x() + step.x(), u0, u1), std::clamp(uv.y() + step.y(), v0, v1));
        const Eigen::Vector2d moved = next - uv;
        uv = next;
        const double size = d.Su.norm() * (u1 - u0) + d.Sv.norm() * (v1 - v0);
        if ((d.Su * moved.x() + d.Sv * moved.y()).norm() <= kFootPointStep * size) {
            const Eigen::Vector3d S = surface.evaluate(uv.x(), uv.y());
            if ((S - x).squaredNorm() < best_d) best = uv;
            break;
        }
    }
    return best;
}

}  // namespace trimkit::tess
