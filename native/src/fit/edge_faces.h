// The faces that use each edge of a model (Model::edges), in face order, once per
// use: two faces for a manifold edge, one face twice for a seam.
#pragma once

#include <vector>

#include "geom/model.h"

namespace trimkit::fit {

using EdgeFaces = std::vector<std::vector<int>>;  // per edge: face indices

EdgeFaces edge_faces(const geom::Model& model);

// The face across coedge (loop, coedge) of `face`, or -1 when its edge is used by
// no other face (or by more than one other).
int neighbour_face(const geom::Model& model, const EdgeFaces& uses, int face, int loop, int coedge);

}  // namespace trimkit::fit
