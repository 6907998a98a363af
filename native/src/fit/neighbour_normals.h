// The unit normal of the face across a coedge's edge at a model-space point (its
// surface's normal at the point's projection), for G1 rows and tangent planes
// ([Muraki] Sec. 4.1-4.2). Projectors are built once per neighbour.
#pragma once

#include <map>
#include <memory>

#include <Eigen/Core>

#include "fit/edge_faces.h"
#include "geom/model.h"
#include "geom/surface_projector.h"

namespace trimkit::fit {

class NeighbourNormals {
public:
    NeighbourNormals(const geom::Model& model, const EdgeFaces& uses, int face)
        : model_(model), uses_(uses), face_(face) {}

    // Throws geom::InvalidInput if the coedge has no neighbour face.
    Eigen::Vector3d at(int loop, int coedge, const Eigen::Vector3d& x);

private:
    const geom::Model& model_;
    const EdgeFaces& uses_;
    int face_;
    std::map<int, std::unique_ptr<geom::SurfaceProjector>> projectors_;
};

}  // namespace trimkit::fit
