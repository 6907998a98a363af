// Holes narrower than a sliver in a joined model mesh. repair_trim_loop drops the
// lobes of a self-crossing trim loop that are narrower than a share of T (two edges
// that meet tangentially at a vertex: their polylines, each within its trim
// tolerance, cross near it; bug32596_abc_0_13.step). The neighbouring faces still
// follow the edges there, so the dropped lobe is a hole in a closed solid, a few
// open edges wide and far narrower than T. Such holes are closed with a fan of
// triangles; the fan lies within about the hole's width of its boundary, which
// both faces' meshes follow.
#pragma once

#include "mesh/mesh.h"

namespace trimkit::tess {

// Boundary cycles of the mesh's position topology (unpaired_sides, positions as
// float as written) of at most `max_sides` sides whose width 2 A / P (A the fan's
// area, P the perimeter: a triangle's inradius, half a thin strip's width) is at
// most `width` are filled with a fan (vertices reused, face id of the cycle's first
// side's triangle), oriented against the sides they close.
// Returns the number of holes filled.
int fill_sliver_holes(mesh::Mesh& mesh, double width, int max_sides, int threads = 1);

}  // namespace trimkit::tess
