// TBP solids from closed triangle meshes: curved PN triangles (Vlachos, Peters,
// Boyd, Mitchell 2001, cited as [VPBM01] in [Garcia] Sec. 2): each triangle
// becomes a cubic TBP from its corner positions and vertex normals. Vertex
// normals are computed here (angle-weighted over the welded mesh), not taken
// from the input, so a shared edge gets the same control points from both sides
// and the solid is watertight. Triangles counter-clockwise seen from outside
// give patches whose normals point out.
#pragma once

#include "mesh/mesh.h"
#include "tbp/tbp_solid.h"

namespace trimkit::tbp {

// Cubic PN-triangle solid of `mesh` (welded first at 1e-9 of its box diagonal).
// Throws InvalidInput for an invalid mesh, one without triangles, or one with a
// vertex where no normal can be formed (its triangles cancel: bad input, named
// by the vertex index in the welded mesh).
TbpSolid pn_triangles(const mesh::Mesh& mesh);

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
