// What a face's geometry costs stored, counted in numbers (doubles): its surface and
// trim curves when it keeps them, or the 3D curves of the edges its compression adds
// (the rule itself is a few bytes). compress_model keeps a face whose compression
// would not save numbers (a circular hole on a plane: its cubic edge outweighs the
// plane and the arcs).
#pragma once

#include <cstddef>
#include <vector>

#include "geom/model.h"

namespace trimkit::fit {

std::size_t kept_numbers(const geom::Face& face);
// Numbers of the curves in `after` that `before` lacks (new edges, or edges given a curve).
std::size_t added_numbers(const std::vector<geom::Edge>& before, const std::vector<geom::Edge>& after);

}  // namespace trimkit::fit
