// Reads any model file trimkit knows, choosing the reader by extension:
// .igs/.iges (read_iges), .stp/.step (read_step, which throws when trimkit was
// built without Open CASCADE), .brep (read_brep), .tkz (read_tkz_model: the
// compressed faces rebuilt); others throw ReadError naming the file.
#pragma once

#include <string>

#include "geom/model.h"
#include "io/read_options.h"

namespace trimkit::io {

// `options`: the read's timeout, cancel flag and progress (read_options.h); a read
// stopped by them throws ReadStopped.
geom::Model read_model(const std::string& path, const ReadOptions& options = {});

}  // namespace trimkit::io
