// Mesh: the output triangle mesh, as bulk arrays (no per-vertex objects).
// Conventions: indices are 0-based int32 into `positions`; triangles run
// counter-clockwise seen from the side their normals point to; optional
// per-vertex and per-triangle arrays are either empty (absent) or have exactly
// one entry per vertex / triangle. Lengths are in the model's units.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace trimkit::mesh {

// Bits of FlaggedEdge::flags.
enum EdgeFlag : std::uint8_t {
    kFaceBoundary = 1,  // the edge lies on the boundary of a CAD face (trim or seam)
    kSharp = 2,         // neighbouring normals differ by more than the sharp angle
};

// One flagged mesh edge. Only edges with at least one flag are stored; the
// pair is unordered (v0 -> v1 and v1 -> v0 name the same edge).
struct FlaggedEdge {
    std::int32_t v0 = 0;
    std::int32_t v1 = 0;
    std::uint8_t flags = 0;  // EdgeFlag bits, never 0
};

struct Mesh {
    // #V positions.
    std::vector<Eigen::Vector3d> positions;
    // Empty, or #V unit normals (from the exact surface, oriented like the face).
    std::vector<Eigen::Vector3d> normals;
    // Empty, or #V (u, v) in the parameters of the surface the vertex lies on.
    std::vector<Eigen::Vector2d> uvs;
    // #T triangles, three vertex indices each, counter-clockwise seen from the normal side.
    std::vector<std::array<std::int32_t, 3>> triangles;
    // Empty, or #T face ids (>= 0): the CAD face (Model::faces index) each triangle comes from.
    std::vector<std::int32_t> face_ids;
    // Flagged edges only (face boundaries, sharp edges), any order, each pair at most once.
    std::vector<FlaggedEdge> edges;
    // Empty, or one rgb colour (each component in [0, 1]) per face id, indexed by face
    // id; when present it covers every face id in `face_ids`.
    std::vector<std::array<float, 3>> face_colors;

    std::size_t vertex_count() const { return positions.size(); }
    std::size_t triangle_count() const { return triangles.size(); }
    bool has_normals() const { return !normals.empty(); }
    bool has_uvs() const { return !uvs.empty(); }
    bool has_face_ids() const { return !face_ids.empty(); }
};

// Normals may differ from unit length by this much and still count as unit:
// far above double rounding (1e-16), below any visible shading difference.
constexpr double kUnitNormalTolerance = 1e-6;

// Throws geom::InvalidInput naming the first bad entry ("Mesh: positions[3] =
// (nan, 0, 0); coordinates must be finite") unless: all values are finite;
// optional arrays are empty or sized as documented; normals are unit within
// kUnitNormalTolerance; triangle and edge indices are in range; face ids are
// >= 0 and covered by face_colors (when present); colours are in [0, 1]; edge
// flags are non-zero and edges join two distinct vertices.
void validate(const Mesh& mesh);

// Appends `part` to `into`: vertices after into's, triangle and edge indices
// offset by into's vertex count. Face ids are kept (they name model faces);
// face colours `into` lacks are taken from `part`. An empty `into` (no vertices,
// no triangles) takes part's optional arrays; otherwise both meshes must carry
// the same optional arrays, or InvalidInput is thrown and `into` is unchanged.
void append(Mesh& into, const Mesh& part);

// Splits `mesh` (with face ids) by a group per face id: part k holds the triangles
// whose face id f has group_of_face[f] == k, in their order, with the vertices they
// use (renumbered in order of first use) and all face colours. Flagged edges are
// dropped (flag the parts, or the mesh they are appended back into). Throws
// InvalidInput for a mesh without face ids, or a face id outside group_of_face or
// whose group is outside [0, groups).
std::vector<Mesh> split_by_face_group(const Mesh& mesh, const std::vector<int>& group_of_face, int groups);

// Sum of the triangles' areas (model units squared).
double surface_area(const Mesh& mesh);

// Smallest axis-aligned box holding every position; an empty box
// (isEmpty() == true) for a mesh without vertices.
Eigen::AlignedBox3d bounding_box(const Mesh& mesh);

}  // namespace trimkit::mesh
