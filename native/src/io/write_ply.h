// Binary little-endian PLY output of a mesh::Mesh. Element `vertex`: float
// x y z, then nx ny nz (if the mesh has normals), then u v (if it has uvs: the
// surface parameters as they are). Element `face`: `list uchar int
// vertex_indices` (0-based, counter-clockwise), then `int face_id` if the mesh
// has face ids. Values are converted from double to float32.
#pragma once

#include <string>

#include "mesh/mesh.h"

namespace trimkit::io {

// Writes `mesh` to `path`. Throws geom::InvalidInput for an invalid mesh or a
// value beyond float32 range, std::runtime_error naming the path when the file
// cannot be written.
void write_ply(const std::string& path, const mesh::Mesh& mesh);

}  // namespace trimkit::io
