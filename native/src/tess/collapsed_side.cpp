#include "tess/collapsed_side.h"

#include <cmath>

#include "geom/surface_projector.h"

namespace trimkit::tess {
namespace {

constexpr double kOnSide = 1e-9;  // of the domain's extent in the collapsing parameter

struct Domain {
    double u0, u1, v0, v1;
};

Domain domain_of(const geom::NurbsSurface& s) {
    const auto [u0, u1] = s.domain_u();
    const auto [v0, v1] = s.domain_v();
    return {u0, u1, v0, v1};
}

// Side k's fixed parameter (0: u, 1: v) and its value.
int fixed_parameter(int side) { return side < 2 ? 0 : 1; }
double side_value(const Domain& d, int side) {
    return side == 0 ? d.u0 : side == 1 ? d.u1 : side == 2 ? d.v0 : d.v1;
}

}  // namespace

CollapsedSides collapsed_sides(const geom::NurbsSurface& s) {
    const Domain d = domain_of(s);
    const double size = s.control_box().diagonal().norm();
    CollapsedSides sides{};
    for (int k = 0; k < 4; ++k) {
        const int fixed = fixed_parameter(k), free = 1 - fixed;
        const double lo = free == 0 ? d.u0 : d.v0, hi = free == 0 ? d.u1 : d.v1;
        bool collapsed = true;
        for (double t : {0.0, 0.5, 1.0}) {
            Eigen::Vector2d uv;
            uv[fixed] = side_value(d, k);
            uv[free] = lo + t * (hi - lo);
            collapsed = collapsed && geom::parameter_is_free(s, uv, free, size);
        }
        sides[k] = collapsed;
    }
    return sides;
}

int touched_collapsed_side(const geom::NurbsSurface& s, const CollapsedSides& sides,
                           const std::vector<Eigen::Vector2d>& uv, const std::vector<int>& ring) {
    const Domain d = domain_of(s);
    for (int k = 0; k < 4; ++k) {
        if (!sides[k]) continue;
        const int fixed = fixed_parameter(k);
        const double eps = kOnSide * (fixed == 0 ? d.u1 - d.u0 : d.v1 - d.v0);
        for (int i : ring)
            if (std::abs(uv[i][fixed] - side_value(d, k)) <= eps) return k;
    }
    return -1;
}

std::vector<Eigen::Vector2d> polar_about_side(const geom::NurbsSurface& s, int side,
                                              const std::vector<Eigen::Vector2d>& uv) {
    const Domain d = domain_of(s);
    const int fixed = fixed_parameter(side), free = 1 - fixed;
    const double from = side_value(d, side);
    const double lo = free == 0 ? d.u0 : d.v0, hi = free == 0 ? d.u1 : d.v1;
    // Orientation: det d(radius, angle)/d(u, v) > 0 for the sign of each side.
    const double radius_sign = side == 0 || side == 2 ? 1.0 : -1.0;
    const double angle_sign = side == 0 || side == 3 ? 1.0 : -1.0;
    const double k = angle_sign * (M_PI / 2) / (hi - lo);
    std::vector<Eigen::Vector2d> out(uv.size());
    for (std::size_t i = 0; i < uv.size(); ++i) {
        const double r = radius_sign * (uv[i][fixed] - from), a = k * (uv[i][free] - lo);
        out[i] = Eigen::Vector2d(r * std::cos(a), r * std::sin(a));
    }
    return out;
}

}  // namespace trimkit::tess
