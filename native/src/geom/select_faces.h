// A model of some of another model's faces (in the order given), for measuring or
// meshing one part of it (a Blender object showing one body). Edges keep their
// indices; bodies and instances are dropped, so every kept face is a free face.
#pragma once

#include <vector>

#include "geom/model.h"

namespace trimkit::geom {

// Throws InvalidInput naming the index if a face index is out of range or repeated.
Model select_faces(const Model& model, const std::vector<int>& faces);

}  // namespace trimkit::geom
