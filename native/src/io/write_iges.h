// Writing a geom::Model as IGES 5.3 ([IGES]), entities in face order so the file
// reads back with the same face indices. A body of consecutive faces whose every
// coedge lies on an edge with a 3D curve becomes a B-rep: 186 manifold solid
// (closed) over a 514 shell of 510 faces with 508 loops on one 504 edge list and
// 502 vertex list, so shared edges stay shared. Other faces become 144 trimmed
// surfaces on 128 rational B-spline surfaces, each loop a 142 curve on surface
// whose parameter and model curves are 102 composite curves of one piece per
// coedge (126 B-spline curves, 110 lines for straight two-point pieces; parameter
// curves in the plane z = 0). Reals are written with 17 significant digits, so our
// reader (read_iges) reads the same numbers back.
#pragma once

#include <string>

#include "geom/model.h"

namespace trimkit::io {

std::string iges_text(const geom::Model& model, const std::string& file_name);
void write_iges(const geom::Model& model, const std::string& path);

}  // namespace trimkit::io
