// Sewing: coedges that the file does not share (IGES faces mode, 144 without 186;
// loose faces of a STEP shell) but whose 3D traces S(c(t)) run along one another get
// one shared Edge, so tessellate_model approximates the curve once and both faces take
// the same polyline (share_edge_points.h): the faces meet by construction instead of
// by a weld of two polylines that each stray within their own tolerance of the curve
// (issue 10: "welded by construction"). Only whole coedges are paired, each at most
// once. First, a coedge on whose interior another free trace ends (within the
// distance) is split there: a curve split differently on its two faces (a T-vertex,
// or closed curves that start at different points) becomes whole pieces that pair.
#pragma once

#include "geom/model.h"

namespace trimkit::tess {

struct SewingReport {
    int pairs = 0;        // coedge pairs that became a shared edge
    int splits = 0;       // coedges split where another trace ends on them
    double max_gap = 0.0; // largest distance between the paired traces (3D)
};

// Pairs free coedges (edge < 0) of `model` whose traces have ends within `distance`
// of each other (either direction) and whose points (9 per trace, each way, mapped
// by share_edge_points) lie within `distance` of the other trace; the closest pair
// wins where a coedge has several. Each pair gets a new Model::edges entry without a
// 3D curve, running along the first coedge (in face order). Traces shorter than
// 2 x distance (poles, collapsed sides) are not paired. Returns what was sewn.
SewingReport sew_free_coedges(geom::Model& model, double distance, int threads = 1);

}  // namespace trimkit::tess
