// The .tkz format (docs/tkz.md): a compact little-endian binary of a model whose
// compressed faces keep only their boundary edges and a fit::FitRule ([Muraki]
// Sec. 2-3), the other faces their surface and parameter curves. Topology (loops,
// coedges on shared edges, bodies, free faces, instances, colours) and the edges'
// 3D curves are stored for every face. Doubles are written bit for bit, so a kept
// face reads back identical and a compressed face refits to the same surface.
#pragma once

#include <string>

#include "fit/compress_model.h"

namespace trimkit::io {

// The file's bytes; throws geom::InvalidInput if a face referred to a missing edge.
std::string tkz_bytes(const fit::CompressedModel& model);
void write_tkz(const fit::CompressedModel& model, const std::string& path);

// Every count is checked against the bytes left before anything is allocated,
// every index against its range, every curve and surface through its validating
// constructor: a damaged or hostile file throws geom::ReadError(file, 0, reason).
fit::CompressedModel read_tkz(const std::string& path);

// read_tkz then fit::extend_model: the model with its compressed faces rebuilt. A
// face that cannot be rebuilt from the file's edges and rules is bad input too:
// ReadError "FILE: a face cannot be rebuilt: ...". `rebuilt` (optional) gets their count.
geom::Model read_tkz_model(const std::string& path, int* rebuilt = nullptr);
fit::CompressedModel read_tkz_bytes(const std::string& bytes, const std::string& name);

}  // namespace trimkit::io
