// Tessellation of a whole model: every face meshed (in parallel, the result
// independent of the thread count), shared edges approximated once so both faces
// use identical boundary points, faces joined into one mesh with coincident
// vertices welded, T-junctions between faces closed, and face-boundary / sharp
// edges flagged. Each face's mesh is verified against the exact trimmed face
// (verify_face) before it is accepted; a rejected face is retried once another way,
// and if it still fails it is reported with its figures and left out of the mesh.
// Faces that fail are reported, the rest still meshed.
// Lengths are in the model's units; the mesh is in model space (instances are
// not applied).
#pragma once

#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "geom/model.h"
#include "mesh/mesh.h"
#include "tess/tessellation_options.h"

namespace trimkit::tess {

// A face left out of the mesh. When its mesh was made but rejected by verify_face
// (after the retry), `defect` says which check failed and the figures are the first
// attempt's (verify_face.h); a face stopped by TessellationOptions::face_timeout has
// defect "timeout" (reason: where it stopped, after how long) and NaN area figures;
// otherwise (an exception, no triangles) `defect` is "error" and the figures are NaN.
struct FailedFace {
    int face = -1;       // Model::faces index
    std::string reason;  // "face 12: mesh area 1.504x the exact trimmed area (...)"
    std::string defect = "error";  // "area", "trim_loop", "boundary", "no_boundary", "timeout" or "error"
    double area_mesh = std::numeric_limits<double>::quiet_NaN();
    double area_exact = std::numeric_limits<double>::quiet_NaN();
    double area_bound = std::numeric_limits<double>::quiet_NaN();  // allowed |area_mesh - area_exact|
    // Largest distance between the trim loops' 3D curves and the mesh boundary (both
    // ways), and the distance allowed.
    double boundary_gap = std::numeric_limits<double>::quiet_NaN();
    double boundary_bound = std::numeric_limits<double>::quiet_NaN();
    double seconds = 0.0;  // wall time spent on the face (all its attempts)
};

// Seconds per stage. Per-face stages run in parallel: their shares of the parallel
// wall time follow their summed thread times.
struct TessellationTimings {
    double trim = 0.0;         // trim curve approximation, loop repair, trimming the cells
    double surface = 0.0;      // kd-tree subdivision
    double triangulate = 0.0;  // triangulation and evaluation
    double weld = 0.0;         // welding, T-junctions, edge flags, open edge count
    double verify = 0.0;       // verify_face on each face's mesh (and on its retry)
};

// Thrown by tessellate_model when options.cancel was set: nothing is returned.
class TessellationCancelled : public std::runtime_error {
public:
    explicit TessellationCancelled(const std::string& what) : std::runtime_error(what) {}
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

// Meshes every face of `model`. Throws geom::InvalidInput for invalid options and
// TessellationCancelled once options.cancel is set; per-face NumericalFailure /
// InvalidInput, rejected meshes and faces over options.face_timeout go to
// failed_faces (their triangles are not in the mesh).
TessellationResult tessellate_model(const geom::Model& model, const TessellationOptions& options);

// Diagonal of the tight bounding box of the trimmed faces, from points on them
// (trim curves and (u,v) grid samples inside the trim loops), not control points:
// the length a --relative tolerance is a fraction of, with the model's instances
// placed (the whole assembly). 0 for a model without faces. Faces are sampled on
// `threads` threads (0: as many as the machine has); the result does not depend on it.
double model_diagonal(const geom::Model& model, int threads = 1);

}  // namespace trimkit::tess
