// Joining separately meshed faces by position. The model mesh keeps one vertex per
// face side (each with its own face's (u,v) and normal; a closed surface's seam keeps
// both sides), so its topology is that of POSITIONS: vertices at exactly the same
// position are one topological vertex (position_groups). Snapping moves vertices of
// open edges that lie within a tolerance onto one position, under two rules: a vertex
// moves by at most the tolerance, and no two vertices of one triangle end up at one
// position, so no triangle degenerates (a plate thinner than the tolerance stays a
// plate); and (with face ids) no two vertices of one face are snapped together.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesh/mesh.h"

namespace trimkit::tess {

// For every vertex the index of the first vertex at exactly the same position
// (positions rounded to float when `as_float`, as a float32 file stores them).
std::vector<std::int32_t> position_groups(const mesh::Mesh& mesh, bool as_float = false, int threads = 1);

// The mesh's triangles with every index replaced by its position group.
std::vector<std::array<std::int32_t, 3>> position_triangles(const mesh::Mesh& mesh,
                                                            const std::vector<std::int32_t>& group);

// Open edges of the position topology (edges used by one triangle, degenerate
// triangle sides skipped), counted with positions rounded to float as written.
std::size_t count_position_open_edges(const mesh::Mesh& mesh, int threads = 1);

// Snaps the vertices of open edges (position topology) that lie within
// `tolerance` (model units, >= 0) onto common positions under the rules above;
// pairs are joined closest first, each cluster's position is that of its
// lexicographically smallest member, so the result does not depend on vertex
// numbering. Returns the number of vertices moved.
// A boundary with more than kMaxSnapPairsPerEnd candidate pairs per open-edge vertex
// is degenerate (a self-crossing trim loop's crossings piled within the tolerance):
// nothing is snapped and *degenerate (if given) is set; the pairs would grow with the
// square of the pile, in time and memory.
constexpr std::size_t kMaxSnapPairsPerEnd = 64;
std::size_t snap_boundary_vertices(mesh::Mesh& mesh, double tolerance, bool* degenerate = nullptr,
                                   int threads = 1);

}  // namespace trimkit::tess
