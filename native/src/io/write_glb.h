// glTF 2.0 binary (.glb) output of a mesh::Mesh: one scene, one node, one mesh
// with one triangle primitive. Attributes POSITION (float32 VEC3 with the
// min/max the spec requires), NORMAL (float32 VEC3, if the mesh has normals) and
// TEXCOORD_0 (float32 VEC2, if it has uvs), indices uint32. glTF puts the uv
// origin at the top left, so TEXCOORD_0 = (u, 1 - v): importers that flip back
// (Blender) show the surface parameters (u, v). Face ids, edge flags and colours
// are not written. Chunks are padded to 4 bytes (JSON with spaces, BIN with zeros);
// a mesh without triangles gives a valid file with an empty scene.
#pragma once

#include <string>

#include "mesh/mesh.h"

namespace trimkit::io {

// Writes `mesh` to `path`. Throws geom::InvalidInput for an invalid mesh or a
// value beyond float32 range, std::runtime_error naming the path when the file
// cannot be written.
void write_glb(const std::string& path, const mesh::Mesh& mesh);

}  // namespace trimkit::io
