// Binary STL output of a mesh::Mesh: an 80-byte header (not starting with
// "solid", so readers do not mistake it for ASCII STL), a uint32 triangle count,
// then per triangle a float32 facet normal, three float32 vertices in the
// triangle's counter-clockwise order and a zero uint16: 84 + 50 n bytes in all.
// Facet normals come from the triangle ((b - a) x (c - a), normalised; zero for a
// degenerate triangle), not from the vertex normals; uvs and face ids are dropped.
#pragma once

#include <string>

#include "mesh/mesh.h"

namespace trimkit::io {

// Writes `mesh` to `path`. Throws geom::InvalidInput for an invalid mesh or a
// position beyond float32 range, std::runtime_error naming the path when the
// file cannot be written.
void write_stl(const std::string& path, const mesh::Mesh& mesh);

}  // namespace trimkit::io
