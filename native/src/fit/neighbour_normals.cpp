#include "fit/neighbour_normals.h"

#include <string>

#include "geom/error.h"

namespace trimkit::fit {

Eigen::Vector3d NeighbourNormals::at(int loop, int coedge, const Eigen::Vector3d& x) {
    const int other = neighbour_face(model_, uses_, face_, loop, coedge);
    if (other < 0)
        throw geom::InvalidInput("face " + std::to_string(face_) + " loop " + std::to_string(loop) + " coedge " +
                                 std::to_string(coedge) + " is G1 but has no neighbour");
    auto& projector = projectors_[other];
    if (!projector) projector = std::make_unique<geom::SurfaceProjector>(model_.faces[other].surface);
    const Eigen::Vector2d uv = projector->invert(x);
    return model_.faces[other].surface.normal(uv.x(), uv.y());
}

}  // namespace trimkit::fit
