// Face-level helpers of the B-rep data model.
#include "geom/face.h"

#include "geom/knot_vector.h"

namespace trimkit::geom {

Loop natural_boundary_loop(const NurbsSurface& surface) {
    const auto [u0, u1] = surface.domain_u();
    const auto [v0, v1] = surface.domain_v();
    return rectangle_loop(u0, u1, v0, v1);
}

// Four degree-1 coedges, each on the parameter interval [0, 1]:
// (u0,v0) -> (u1,v0) -> (u1,v1) -> (u0,v1) -> (u0,v0), counter-clockwise in (u,v).
Loop rectangle_loop(double u0, double u1, double v0, double v1) {
    const Eigen::Vector2d corners[4] = {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}};
    Loop loop;
    loop.outer = true;
    loop.coedges.reserve(4);
    for (int i = 0; i < 4; ++i) {
        Coedge coedge;
        coedge.curve = NurbsCurve2d(1, bezier_knots(1), {corners[i], corners[(i + 1) % 4]});
        loop.coedges.push_back(std::move(coedge));
    }
    return loop;
}

}  // namespace trimkit::geom
