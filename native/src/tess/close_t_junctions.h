// Closing T-junctions between faces: where a boundary vertex of one face lies on
// an open boundary edge of another (both faces put their grid crossings on the
// same 3D chord of a shared edge, at different places), the edge's triangle is
// split at that vertex. Positions do not move, so the geometry is unchanged.
// Topology is by position (snap_boundary_vertices.h): the split inserts a new
// vertex of the split triangle's face at the other face's vertex position, with
// (u,v) and normal interpolated along the split edge, so every vertex keeps its
// own face's parameters.
#pragma once

#include <cstddef>

#include "mesh/mesh.h"

namespace trimkit::tess {

// Splits triangles on open edges at boundary vertices lying on those edges within
// `distance` (model units, >= 0) and strictly between their ends. Face ids follow
// the split triangle; flagged edges are left as they are (recompute them). Returns the number of
// vertices inserted into edges.
// A pass that tests more than kMaxJunctionTestsPerSide vertices per open side meets a
// degenerate boundary (a self-crossing trim loop's crossings piled together): it stops
// after the side it is on (the sides done so far stay split), no further pass runs,
// and *degenerate (if given) is set; the tests and splits would grow with the square
// of the pile.
constexpr std::size_t kMaxJunctionTestsPerSide = 256;
std::size_t close_t_junctions(mesh::Mesh& mesh, double distance, bool* degenerate = nullptr, int threads = 1);

}  // namespace trimkit::tess
