// Welding: merging vertices closer than a distance tolerance, found with a
// uniform hash grid of cell size >= tolerance (27 neighbouring cells per query).
// Clusters are grown greedily around representatives taken in lexicographic
// order of (position, normal, uv), so which vertices merge, and where they end
// up, does not depend on the order of the input vertices (only exactly equal
// vertices are told apart by index). Merging is not transitive: every vertex of
// a cluster lies within the tolerance of its representative.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/mesh.h"

namespace trimkit::mesh {

struct WeldOptions {
    // Vertices at most this far (Euclidean, model units) from a representative
    // merge into it. >= 0; 0 merges exactly coincident vertices only.
    double tolerance = 0.0;
    // When true (and the mesh has normals), vertices whose normals differ by more
    // than split_normal_angle stay separate, so creases keep their split normals.
    bool keep_split_normals = false;
    double split_normal_angle = 1e-3;  // radians
    // When true (and the mesh has uvs), vertices with different uvs stay separate:
    // a closed surface's seam, or two CAD faces meeting along an edge, keep each
    // side's own (u,v) (the mesh is then closed by position, not by index).
    bool keep_split_uvs = false;
    // With keep_split_uvs: uvs at most this far apart (parameter units) count as equal.
    double split_uv_distance = 0.0;
    // Drop triangles that lose an edge by welding (two equal indices), with their face ids.
    bool remove_degenerate_triangles = true;
};

struct WeldResult {
    // #V_in entries: the welded index of every input vertex.
    std::vector<std::int32_t> vertex_map;
    std::int32_t vertex_count = 0;        // #V_out
    std::int32_t removed_triangles = 0;   // degenerate triangles dropped (0 from weld_map)
};

// The welded index of every vertex, without changing the mesh (the map of
// weld_vertices). Welded vertices are numbered in order of their first input
// vertex, so a mesh without close vertices maps to itself. Callers that want to
// keep per-corner uvs or normals (a Blender loop layer) can use this map for the
// corners' vertices and keep the attributes of the original vertices.
// Throws geom::InvalidInput for an invalid mesh (see validate) or a negative or
// non-finite tolerance or angle.
WeldResult weld_map(const Mesh& mesh, const WeldOptions& options);

// Welds `mesh` in place: each welded vertex keeps the position, normal and uv of
// its cluster's representative (the lexicographically smallest (position, normal,
// uv) in the cluster); triangle and edge indices are remapped, edges that
// collapse are dropped and duplicates merged (flags or-ed). Validates the mesh
// first (InvalidInput); on a throw `mesh` is unchanged.
WeldResult weld_vertices(Mesh& mesh, const WeldOptions& options);

}  // namespace trimkit::mesh
