// 3D edge curves for the coedges of a face that have none: a face rebuilt from
// its boundary ([Muraki] Sec. 2) needs every boundary edge in model space, but
// files without B-rep topology (IGES 144 without 3D curves, free faces) give only
// parameter curves. The image S(c(t)) of the coedge's curve is fitted (fit_curve
// through its exact end points, chord-length parameters) by a line when it is one
// within the tolerance, else by a cubic with as few control points as keep it so.
#pragma once

#include "geom/model.h"

namespace trimkit::fit {

// Each coedge of model.faces[face] whose edge is -1 gets a new Edge appended to
// model.edges (edge_reversed false); a shared edge without a curve gets its curve
// from this face. Returns false, changing nothing, when some curve cannot be
// fitted within `tolerance` (model units) with fit_curve's most control points.
bool add_coedge_edges(geom::Model& model, int face, double tolerance);

}  // namespace trimkit::fit
