#include "fit/periodic_face.h"

#include <algorithm>
#include <set>

#include "geom/extend_closed_surface.h"

namespace trimkit::fit {

bool is_periodic_face(const geom::Face& f, double size) {
    std::set<int> seen;
    Eigen::AlignedBox2d uv;
    for (const geom::Loop& loop : f.loops)
        for (const geom::Coedge& c : loop.coedges) {
            if (c.edge >= 0 && !seen.insert(c.edge).second) return true;  // a seam
            uv.extend(c.curve.control_box());
        }
    const double tolerance = 1e-7 * std::max(size, 1e-300);
    const auto [u0, u1] = f.surface.domain_u();
    const auto [v0, v1] = f.surface.domain_v();
    if (geom::is_closed_surface(f.surface, 0, tolerance) && uv.sizes().x() >= kPeriodicSpan * (u1 - u0)) return true;
    if (geom::is_closed_surface(f.surface, 1, tolerance) && uv.sizes().y() >= kPeriodicSpan * (v1 - v0)) return true;
    return false;
}

}  // namespace trimkit::fit
