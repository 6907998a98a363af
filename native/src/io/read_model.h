// Reads any model file trimkit knows, choosing the reader by extension:
// .igs/.iges (read_iges), .stp/.step (read_step, which throws when trimkit was
// built without Open CASCADE), .brep (read_brep), .tkz (read_tkz_model: the
// compressed faces rebuilt); others throw ReadError naming the file.
#pragma once

#include <string>

#include "geom/model.h"

namespace trimkit::io {

geom::Model read_model(const std::string& path);

}  // namespace trimkit::io
