// TBP solids from closed triangle meshes: curved PN triangles (Vlachos, Peters,
// Boyd, Mitchell 2001, cited as [VPBM01] in [Garcia] Sec. 2): each triangle
// becomes a cubic TBP from its corner positions and vertex normals. Vertex
// normals are computed here (angle-weighted over the welded mesh), not taken
// from the input, so a shared edge gets the same control points from both sides
// and the solid is watertight. Triangles counter-clockwise seen from outside
// give patches whose normals point out.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "mesh/mesh.h"
#include "tbp/tbp_solid.h"

namespace trimkit::tbp {

// Cubic PN-triangle solid of `mesh` (welded first at 1e-9 of its box diagonal).
// A side whose two triangles' normals differ by more than `sharp_angle` (radians;
// the default keeps every side smooth), or whose two vertices are a pair of
// `sharp_edges` (indices into mesh.positions, either order: the edges a user marked
// sharp), is a crease: its edge points lie on the straight side for both
// triangles, and each corner's normal is averaged only over the triangles no
// crease separates from it, so a cube stays a cube. A pair that is no side of the
// mesh is ignored.
// Throws InvalidInput for an invalid mesh, one without triangles, a negative or NaN
// sharp_angle, a sharp_edges index outside the mesh, or a vertex where no normal
// can be formed (its triangles cancel: bad input, named by the vertex index in the
// welded mesh).
constexpr double kNoSharpEdges = 4.0;  // more than pi: no side is a crease
using VertexPairs = std::vector<std::pair<std::int32_t, std::int32_t>>;
TbpSolid pn_triangles(const mesh::Mesh& mesh, double sharp_angle = kNoSharpEdges,
                      const VertexPairs& sharp_edges = {});

struct LoopConversion {
    TbpSolid solid;            // one quartic patch per cage triangle
    int approximated = 0;      // patches that differ from the limit surface (irregular ones)
    double max_error = 0;      // largest distance between patch and limit surface found (model units)
};

// Quartic TBP solid of the Loop subdivision limit surface of a closed triangle
// cage (welded first), through OpenSubdiv's Bfr (Loop scheme). Each patch
// interpolates the limit surface at the 15 points (i,j,k)/4 of its face: where
// the limit is a quartic box spline (all three vertices regular, valence 6)
// this is exact; elsewhere it approximates, and the error measured at a finer
// pattern is reported. A shared edge's 5 control points depend only on limit
// points on that edge, so neighbouring patches match. Throws InvalidInput for
// an invalid mesh, NumericalFailure if trimkit was built without OpenSubdiv or
// OpenSubdiv cannot build a face's surface.
LoopConversion loop_quartics(const mesh::Mesh& cage);

}  // namespace trimkit::tbp
