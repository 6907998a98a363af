// Making trim loops read from files usable: consecutive coedges must meet in
// (u,v) and loops must run the way face.h fixes (outer counter-clockwise, holes
// clockwise, both mirrored for a reversed face). Files give small gaps from
// rounding, pieces out of order, and nothing at all across degenerate edges
// (poles); these functions snap, reorder and bridge, and say so when it matters.
#pragma once

#include <string>
#include <vector>

#include "geom/face.h"

namespace trimkit::io {

// Gaps between coedge ends below this fraction of the domain size are snapped
// (the end control point moved): rounding in files is ~1e-10, pieces that are
// genuinely apart are far above 1e-4.
constexpr double kSnapGapRelative = 1e-4;

// Orders the coedges into a chain when they are out of order, closes gaps (snap
// small ones, bridge larger ones with straight coedges). A bridge whose ends
// lie more than `model_tolerance` apart on the surface adds a message to
// `warnings` (`label` names the loop). Returns false if the loop is empty.
bool close_loop(geom::Loop& loop, const geom::NurbsSurface& surface, double model_tolerance,
                const std::string& label, std::vector<std::string>* warnings);

// Signed area enclosed by the loop in (u,v) (positive: counter-clockwise),
// from a polygon through samples of its coedges.
double signed_area(const geom::Loop& loop);

// The loop that encloses the others: the one of largest |signed_area| whose (u,v)
// control-point box contains the sampled box of loop `declared` (the file's outer
// loop; loops touching it still count), else `declared`.
// Some writers flag a hole as the outer loop (UKI60998.igs lists a circular hole
// first; OCCT's IGES B-rep writer flags a hole of a cylinder whose seam runs through
// another hole); two loops side by side (bands of a closed surface) keep the flag.
std::size_t enclosing_loop(const std::vector<geom::Loop>& loops, std::size_t declared);

// Reverses the loop (order, curves and edge_reversed) when its direction is
// not the one asked for.
void orient_loop(geom::Loop& loop, bool counter_clockwise);

}  // namespace trimkit::io
