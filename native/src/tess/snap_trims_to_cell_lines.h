// Trim points a hair off a cell line. A trim along a knot line (a fillet's quarter
// tube bounded by the torus's iso-line v = pi/2, where its Bezier patches meet) comes
// out of the trim approximation a few 1e-10 either side of the line. Cells are half-
// open, so such a trim leaves the cell above and comes back again and again, and the
// cell's kept region falls apart into slivers (filleted_holes_block_brep.igs: whole
// cells lost, the face failed at 6.8 T). Snapped onto the line, the trim lies on
// the cell above as trim_cells expects (a point on a side belongs to the cell above).
#pragma once

#include <vector>

#include "tess/kd_subdivision.h"
#include "tess/trim_polyline.h"

namespace trimkit::tess {

// Moves each (u,v) coordinate of the loops' points that lies within `eps` of a u or
// v line of the grid's cells onto that line (the nearest); xyz is kept. Returns the
// number of coordinates moved. `eps` must be below the grid's margin beyond the
// loops, or trim points would snap onto the grid's outer boundary.
int snap_trims_to_cell_lines(std::vector<TrimPolygon>& loops, const CellGrid& grid, double eps);

// The same onto the surface's knot lines, before the kd subdivision: a trim that
// wobbles across a knot line gets an unbounded crossing offset there (C^0 across it)
// and its cells are split far below the tolerance.
int snap_trims_to_knot_lines(std::vector<TrimPolygon>& loops, const geom::NurbsSurface& surface, double eps);

}  // namespace trimkit::tess
