// Tessellation of one trimmed face from its approximated trim loops: kd-tree
// cells [Balazs] Sec. 5.2, trimming Sec. 6, triangulation Sec. 7 and evaluation
// Sec. 8. Interior vertices are S(u,v); trim vertices keep the xyz of their trim
// polygon (crossings interpolate it), so faces sharing an edge meet exactly.
// Normals are the exact surface normals, flipped (with the triangle winding) when
// the face is reversed.
#pragma once

#include <vector>

#include "geom/face.h"
#include "mesh/deadline.h"
#include "mesh/mesh.h"
#include "tess/tessellation_options.h"
#include "tess/trim_polyline.h"

namespace trimkit::tess {

// Seconds spent in the stages of tessellate_face (added to, not reset).
struct FaceTimings {
    double surface = 0.0;      // kd-tree subdivision
    double trim = 0.0;         // trimming the cells
    double triangulate = 0.0;  // triangulation and evaluation
};

// The mesh of `face` bounded by `loops` (closed polygons in the face's (u,v)
// domain; outer loops counter-clockwise, holes clockwise; loops with the wrong
// orientation for their `outer` flag are reversed). Every triangle gets `face_id`;
// edges along the loops are flagged mesh::kFaceBoundary. In kGuaranteed mode every
// point of the mesh lies within interior_tolerance(options) of S at its (u,v) away
// from the loops, and within options.tolerance in cells the loops cross (the cell's
// bound plus its crossings' offset from S; tessellation_options.h), for loops whose
// vertices lie on S. On faces revolution_shape recognises (surfaces of revolution with
// a line or circle meridian) the same shares bound the distance to S instead
// (revolution_error.h), which is what DESIGN.md guarantees and `trimkit check` measures.
// Throws geom::InvalidInput for invalid options or non-finite loop points, and
// geom::NumericalFailure naming the face on degenerate data; never returns NaNs.
// `deadline` (the caller's: tessellate_model gives each face options.face_timeout) is
// checked in the kd subdivision, trimming, triangulation and evaluation loops; once it
// has passed, mesh::DeadlineExceeded is thrown (options.face_timeout is not read here).
mesh::Mesh tessellate_face(const geom::Face& face, const std::vector<TrimPolygon>& loops,
                           const TessellationOptions& options, int face_id,
                           FaceTimings* timings = nullptr, mesh::Deadline* deadline = nullptr);

}  // namespace trimkit::tess
