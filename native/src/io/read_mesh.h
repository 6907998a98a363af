// Reading back the mesh formats trimkit writes (write_obj, write_ply, write_stl,
// write_glb) into a mesh::Mesh, for `trimkit check` and round-trip tests. The
// reader is chosen by extension (case-insensitive). What each format carries:
//   .ply  binary little-endian or ascii; x y z [nx ny nz] [u v] per vertex,
//         vertex_indices (polygons fanned) [face_id] per face
//   .obj  v / vt / vn / f (polygons fanned, negative indices); `g face_N` groups
//         give face ids; corners whose v, vt, vn indices differ split vertices
//   .stl  binary or ascii; exactly coincident corners share one vertex
//   .glb  glTF 2.0 binary: every triangle primitive of every mesh (node
//         transforms are not applied); TEXCOORD_0 t is flipped back (v = 1 - t)
// Input is treated as hostile: counts are checked against the file size before
// anything is allocated, every index is range-checked, non-finite values are
// rejected. Errors are geom::ReadError(file, line or 0, reason).
#pragma once

#include <string>

#include "mesh/mesh.h"

namespace trimkit::io {

// The mesh in `path`; the result passes mesh::validate.
mesh::Mesh read_mesh(const std::string& path);

mesh::Mesh read_ply(const std::string& path);
mesh::Mesh read_obj(const std::string& path);
mesh::Mesh read_stl(const std::string& path);
mesh::Mesh read_glb(const std::string& path);

// The same for file contents already in memory (the fuzz harnesses, tests);
// `file` names the input in errors.
mesh::Mesh parse_ply(const std::string& bytes, const std::string& file);
mesh::Mesh parse_obj(const std::string& bytes, const std::string& file);
mesh::Mesh parse_stl(const std::string& bytes, const std::string& file);
mesh::Mesh parse_glb(const std::string& bytes, const std::string& file);

}  // namespace trimkit::io
