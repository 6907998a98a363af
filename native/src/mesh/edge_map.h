// The edge list of a triangle mesh as Blender stores it: every undirected edge once,
// and for each triangle corner the edge running from it to the next corner
// (MeshLoop.edge_index). Linear time: edges are bucketed by their smaller vertex.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace trimkit::mesh {

struct EdgeMap {
    std::vector<std::array<std::uint32_t, 2>> edges;  // (smaller, larger), in order of first use
    std::vector<std::uint32_t> corner_edges;          // 3 per triangle: corner k -> corner k+1
};

// Throws geom::InvalidInput if an index is outside [0, vertex_count).
EdgeMap edge_map(const std::vector<std::array<std::int32_t, 3>>& triangles, std::size_t vertex_count);

}  // namespace trimkit::mesh
