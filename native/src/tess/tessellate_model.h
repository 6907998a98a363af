// Tessellation of a whole model: every face meshed (in parallel, the result
// independent of the thread count), shared edges approximated once so both faces
// use identical boundary points, faces joined into one mesh with coincident
// vertices welded, T-junctions between faces closed, and face-boundary / sharp
// edges flagged. Faces that fail are reported, the rest still meshed.
// Lengths are in the model's units; the mesh is in model space (instances are
// not applied).
#pragma once

#include <string>
#include <vector>

#include "geom/model.h"
#include "mesh/mesh.h"
#include "tess/tessellation_options.h"

namespace trimkit::tess {

struct FailedFace {
    int face = -1;       // Model::faces index
    std::string reason;  // the exception's message
};

// Seconds per stage. Per-face stages run in parallel: their shares of the parallel
// wall time follow their summed thread times.
struct TessellationTimings {
    double trim = 0.0;         // trim curve approximation, loop repair, trimming the cells
    double surface = 0.0;      // kd-tree subdivision
    double triangulate = 0.0;  // triangulation and evaluation
    double weld = 0.0;         // welding, T-junctions, edge flags, open edge count
};

struct TessellationResult {
    mesh::Mesh mesh;
    int faces = 0;           // faces in the model
    int faces_meshed = 0;    // faces with at least one triangle
    std::vector<FailedFace> failed_faces;
    std::size_t open_edges = 0;  // boundary edges of the welded mesh
    double tolerance = 0.0;      // absolute tolerance used
    TessellationTimings seconds;
    std::vector<std::string> warnings;  // per-face repairs and edge gaps
};

// Meshes every face of `model`. Throws geom::InvalidInput for invalid options;
// per-face NumericalFailure / InvalidInput go to failed_faces.
TessellationResult tessellate_model(const geom::Model& model, const TessellationOptions& options);

// Diagonal of the tight bounding box of the trimmed faces, from points on them
// (trim curves and (u,v) grid samples inside the trim loops), not control points:
// the length a --relative tolerance is a fraction of, with the model's instances
// placed (the whole assembly). 0 for a model without faces.
double model_diagonal(const geom::Model& model);

}  // namespace trimkit::tess
