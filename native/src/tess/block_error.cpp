#include "tess/block_error.h"

#include <limits>

#include "tess/derivative_bounds.h"

namespace trimkit::tess {

BlockError block_error(const geom::NurbsSurface& S, const Eigen::AlignedBox2d& r) {
    constexpr double kInfinity = std::numeric_limits<double>::infinity();
    if (!is_c1_inside(S, r)) return {kInfinity, kInfinity, kInfinity};
    const SurfaceDerivativeBounds M = surface_derivative_bounds(S, r);
    const double du = r.sizes().x(), dv = r.sizes().y();
    BlockError e;
    e.u_term = M.Muu * du * du / 8.0;
    e.v_term = M.Mvv * dv * dv / 8.0;
    e.bound = e.u_term + M.Muv * du * dv / 4.0 + e.v_term;
    if (!std::isfinite(e.bound)) return {kInfinity, kInfinity, kInfinity};
    return e;
}

}  // namespace trimkit::tess
