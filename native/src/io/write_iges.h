// Writing a geom::Model as IGES 5.3 ([IGES]): each face a 144 trimmed surface on a
// 128 rational B-spline surface, each loop a 142 curve on surface whose parameter
// curve and model curve are 102 composite curves of one piece per coedge (126
// B-spline curves, 110 lines for straight two-point pieces; parameter curves in
// the plane z = 0). No B-rep (186/514): faces come back as free faces. Reals are
// written with 17 significant digits, so our reader (read_iges) reads the same
// numbers back.
#pragma once

#include <string>

#include "geom/model.h"

namespace trimkit::io {

std::string iges_text(const geom::Model& model, const std::string& file_name);
void write_iges(const geom::Model& model, const std::string& path);

}  // namespace trimkit::io
