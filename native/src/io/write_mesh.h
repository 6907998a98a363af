// Writes a mesh::Mesh to a file whose format is chosen by extension
// (case-insensitive): .obj (write_obj), .ply (write_ply), .stl (write_stl),
// .glb (write_glb), each with its default options.
#pragma once

#include <string>

#include "mesh/mesh.h"

namespace trimkit::io {

// Writes `mesh` to `path`. Throws geom::InvalidInput for an unknown extension
// or an invalid mesh, std::runtime_error naming the path when the file cannot
// be written.
void write_mesh(const std::string& path, const mesh::Mesh& mesh);

}  // namespace trimkit::io
