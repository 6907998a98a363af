// Edge-use statistics of a triangle mesh: boundary (open) edges, used by
// exactly one triangle; non-manifold edges, used by more than two; and
// misoriented edges, used by two triangles in the same direction. Edges are
// identified by vertex index, so a mesh must be welded (weld_vertices) before
// its seams count as closed. A watertight, consistently oriented mesh has none.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "mesh/mesh.h"

namespace trimkit::mesh {

struct EdgeUses {
    std::array<std::int32_t, 2> vertices;  // (smaller index, larger index)
    std::int32_t count = 0;                // number of triangles using the edge
};

struct OpenEdges {
    // Edges used by one triangle, as (v0, v1) in that triangle's direction, so
    // the boundary of a counter-clockwise patch runs counter-clockwise.
    std::vector<std::array<std::int32_t, 2>> boundary;
    // Edges used by more than two triangles.
    std::vector<EdgeUses> non_manifold;
    // Edges used by exactly two triangles that traverse them in the same
    // direction (the triangles' orientations disagree), as (smaller, larger).
    std::vector<std::array<std::int32_t, 2>> misoriented;

    bool closed() const { return boundary.empty() && non_manifold.empty(); }
};

// All boundary, non-manifold and misoriented edges of `mesh`, each list sorted
// by (smaller index, larger index). Degenerate triangles (a repeated index)
// contribute only their non-degenerate edges. Throws geom::InvalidInput for an
// invalid mesh (see validate).
OpenEdges open_edges(const Mesh& mesh);

// Number of edges with an unpaired use: used by one triangle, or by an odd number
// (a chord used three times is a boundary edge hidden under a sliver).
std::size_t count_open_edges(const Mesh& mesh);

}  // namespace trimkit::mesh
