// The surface interpolation method that [Muraki] Sec. 3 (Fig. 3) applies first to a
// four-sided region without holes: here the bilinearly blended Coons patch of the
// face's four edges (re-derived; the paper uses Gregory patches [11]),
//   S(u,v) = (1-v) C0(u) + v C2(1-u) + (1-u) C3(1-v) + u C1(v) - bilinear(corners),
// C0..C3 the coedges in loop order at their normalised edge parameter, approximated
// by a B-spline of the rule's degrees and counts (fit_surface on a grid of the patch)
// with G1 rows along the coedges the rule marks. Exact in the limit for ruled and
// translational faces (a half cylinder between two semicircles and two lines),
// which the boundary fit cannot parameterise over one reference plane (Sec. 6).
#pragma once

#include "fit/edge_faces.h"
#include "fit/fit_rule.h"
#include "geom/model.h"

namespace trimkit::fit {

// Grid sections per direction of the sampled Coons patch.
constexpr int kCoonsGrid = 24;

// One loop of four coedges, each on an edge with a 3D curve.
bool coons_applicable(const geom::Face& face, const std::vector<geom::Edge>& edges);

// Throws geom::InvalidInput if !coons_applicable or a G1 coedge has no neighbour.
geom::NurbsSurface coons_fill(const geom::Model& model, const EdgeFaces& uses, int face, const FitRule& rule);

}  // namespace trimkit::fit
