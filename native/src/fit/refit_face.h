// The surface of one face rebuilt from its boundary edges ([Muraki] Sec. 4, STEPs
// 1-3): boundary samples on the edges, the local frame and reference planes
// (Sec. 4.1), a tangent plane per sample (the G1 neighbour's, else the one
// interpolated from the loop's corners, corner_normals, else the one through the
// edge tangent closest to the reference plane), cross-boundary lines and their
// samples outside the region (Sec. 4.3), the four boundary curves (Sec. 4.1), and
// the least-squares surface with G1 rows along the G1 coedges (Sec. 4.2, 4.3).
// Departure (Sec. 4.2): the paper restrains the second control-point row of a
// surface whose boundary is the G1 edge; here the G1 edges are trim curves of a
// surface over the reference plane, so G1 is imposed by the linear rows
// n·S_u = n·S_v = 0 at every boundary sample of the edge (fit_surface).
#pragma once

#include "fit/edge_faces.h"
#include "fit/fit_rule.h"
#include "fit/local_frame.h"
#include "geom/model.h"

namespace trimkit::fit {

// Samples per coedge on the boundary edges.
constexpr int kBoundarySamplesPerCoedge = 24;
// Weight of a boundary sample against one outside sample: the surface must pass
// through the edges (Sec. 4.4 checks them), the outside samples only guide it.
constexpr double kBoundaryWeight = 10.0;
// Weight of the G1 rows against the points (fit_surface's tangent_weight): high
// enough that the normals along a G1 edge agree to well under 0.5°.
constexpr double kG1Weight = 100.0;
// Smoothing of the surface fit (thin-plate energy against the mean squared error).
constexpr double kSurfaceSmoothing = 1e-6;

struct RefitResult {
    geom::NurbsSurface surface;  // on [0, 1]², (u, v) = frame.uv of its points, roughly (kBoundaryG1)
    LocalFrame frame;            // kBoundaryG1 only
};

// rule.method kCoons: coons_fill instead (the four-sided interpolation of Sec. 3).
// Uses model.edges for the face's boundary and model.faces[n].surface of every
// neighbour n across a coedge that rule.g1 marks (never the face's own surface).
// Throws geom::InvalidInput if a coedge has no 3D edge or a G1 coedge no
// neighbour, geom::NumericalFailure if the fit is degenerate.
RefitResult refit_face(const geom::Model& model, const EdgeFaces& uses, int face, const FitRule& rule);

}  // namespace trimkit::fit
