// Per-corner (u,v) and normals of a model's mesh, for loop layers (Blender UV maps,
// custom split normals). Welding gives a vertex shared by two CAD faces the (u,v)
// and normal of only one of them, and a closed surface's seam vertex one side of
// the seam; here every triangle corner gets them in its own face's parameters.
// Corner k of triangle t is entry 3t + k. Normals are unit, oriented like the face.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "geom/model.h"
#include "mesh/mesh.h"

namespace trimkit::tess {

struct CornerAttributes {
    std::vector<Eigen::Vector2d> uvs;      // 3 #T, in the face's (u,v) domain
    std::vector<Eigen::Vector3d> normals;  // 3 #T, unit
};

// Corners whose vertex is used by one face only keep the vertex's uv and normal;
// corners of a vertex shared with other faces are inverted onto their own face's
// surface (geom::SurfaceProjector, started from a same-face neighbour). On closed
// surfaces a triangle straddling the seam has its minority corners moved by one
// period so its (u,v) triangle stays small. Throws geom::InvalidInput unless the
// mesh has face ids naming faces of `model`, uvs and normals.
CornerAttributes corner_attributes(const geom::Model& model, const mesh::Mesh& mesh);

}  // namespace trimkit::tess
