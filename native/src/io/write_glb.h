// glTF 2.0 binary (.glb) output of a mesh::Mesh: one scene, one node, one mesh
// with one triangle primitive. Attributes POSITION (float32 VEC3 with the
// min/max the spec requires), NORMAL (float32 VEC3, if the mesh has normals) and
// TEXCOORD_0 (float32 VEC2, if it has uvs), indices uint32. glTF puts the uv
// origin at the top left, so TEXCOORD_0 = (u, 1 - v): importers that flip back
// (Blender) show the surface parameters (u, v). Face ids, edge flags and colours
// are not written. Chunks are padded to 4 bytes (JSON with spaces, BIN with zeros);
// a mesh without triangles gives a valid file with an empty scene.
// An assembly is written with instancing: each part's mesh stored once and placed by
// one node per placement (its 4x4 matrix, glTF spec Sec. 3.5.3; a mirroring matrix is
// allowed, glTF readers reverse the winding of such nodes).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

#include "mesh/mesh.h"

namespace trimkit::io {

// One placed copy of meshes[mesh]: model = matrix * part (affine, last row 0 0 0 1).
struct GlbNode {
    int mesh = 0;
    Eigen::Matrix4d matrix = Eigen::Matrix4d::Identity();
    std::string name;  // written when not empty
};

// Writes `mesh` to `path`. Throws geom::InvalidInput for an invalid mesh or a
// value beyond float32 range, std::runtime_error naming the path when the file
// cannot be written.
void write_glb(const std::string& path, const mesh::Mesh& mesh);

// Writes every mesh once and one node per entry of `nodes` (in that order). Nodes of
// meshes without triangles are left out. Throws geom::InvalidInput as above, for a
// node whose mesh index is out of range, or for a matrix that is not finite or affine.
void write_glb(const std::string& path, const std::vector<mesh::Mesh>& meshes, const std::vector<GlbNode>& nodes);

}  // namespace trimkit::io
