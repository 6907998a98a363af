// Reading IGES 5.3 files into a geom::Model: trimmed and bounded surfaces,
// B-rep solids with shared edges, surfaces with their natural boundary, 124
// transforms applied, and 308/408 subfigures as Model::instances of one body per
// definition (geom::flatten_instances gives every placement's faces). Lengths stay in the file's units (Model::units,
// Model::scale_to_metres).
#pragma once

#include <string>

#include "geom/model.h"
#include "io/read_options.h"

namespace trimkit::io {

// Reads the file at `path`. Throws geom::ReadError ("FILE:LINE: reason") when
// the file cannot be opened, is not IGES, is truncated, or none of its surface
// entities yields a face. Entities that cannot be read (unsupported types,
// broken data, dangling pointers) are skipped with a message in
// Model::warnings ("D123: ..."); per-face remarks go to Face::warnings.
// `options`: timeout and cancel checked between root entities (ReadStopped), progress
// reported as the fraction of directory entries done (parsing the text first: 0.1).
geom::Model read_iges(const std::string& path, const ReadOptions& options = {});

// The same for IGES text already in memory; `name` is used in messages.
geom::Model read_iges_text(const std::string& text, const std::string& name, const ReadOptions& options = {});

}  // namespace trimkit::io
