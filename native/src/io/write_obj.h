// Wavefront OBJ output of a mesh::Mesh: `v` positions, `vt` uvs (the surface
// parameters (u, v) as they are), `vn` normals, and `f` lines with 1-based
// v/vt/vn indices in the triangles' counter-clockwise order. Numbers are the
// shortest text that reads back as the same double.
#pragma once

#include <string>

#include "mesh/mesh.h"

namespace trimkit::io {

struct ObjOptions {
    // Start a `g face_N` group wherever the face id changes (meshes with face ids).
    bool face_groups = true;
    // With face ids and face colours: `usemtl color_RRGGBB` wherever the colour
    // changes, and a material library PATH_STEM.mtl written beside the OBJ (`Kd`
    // from the colour). Ignored for meshes without face colours.
    bool materials = false;
};

// Writes `mesh` to `path` (and the .mtl, see ObjOptions::materials). Throws
// geom::InvalidInput for an invalid mesh (mesh::validate), std::runtime_error
// naming the path when a file cannot be written.
void write_obj(const std::string& path, const mesh::Mesh& mesh, const ObjOptions& options = {});

}  // namespace trimkit::io
