// Turning a face's trim loop into valid polygons for trimming: the coedges'
// polylines joined into one closed polygon (duplicate joints removed, tiny gaps
// snapped), then self-intersections repaired by inserting the crossing points and
// splitting into simple loops ([Balazs] Sec. 5.1, last paragraph), zero-area
// slivers dropped, and each loop oriented in (u,v): outer loops counter-clockwise,
// holes clockwise, whatever Face::reversed says (it only flips the normal).
#pragma once

#include <vector>

#include "geom/nurbs_surface.h"
#include "mesh/deadline.h"
#include "tess/trim_polyline.h"

namespace trimkit::tess {

// A piece of a self-crossing loop whose mean width on the surface (twice its area
// over its perimeter) is below min_width is dropped only if no point of it lies
// farther than this many min_widths from its boundary: a long zero-width lobe
// (a cut running back along a coil's seam, 300 T long on bug22869_Spring.igs)
// attached to a wide region has a small mean width however wide the region is.
// 5: a region whose interior reaches 0.05 T (min_width = 0.01 T) past its boundary
// is no sliver; the boundary is measured on the surface (S at the piece's (u,v),
// refined until its chords sag less than min_width / 2), so the trim chords'
// own sag (up to the trim tolerance, T / 2) does not count as width.
constexpr double kWideRegionFactor = 5.0;

// What the repair changed, for the face's warnings.
struct LoopRepairReport {
    bool reoriented = false;  // the loop ran against face.h's convention for its role
    int crossings = 0;        // self-intersections (crossing or touching points) found
    int split_loops = 0;      // extra simple loops the crossings created
    int dropped = 0;          // slivers (area below snap width x perimeter, or narrower than min_width) dropped
    double max_gap = 0.0;     // largest (u,v) gap between consecutive coedges
    // With a surface: the widest dropped piece (twice the largest distance from a
    // point inside it to its boundary, model units; at most 2 kWideRegionFactor
    // min_width by construction) and the dropped pieces' total area on the surface.
    double dropped_width = 0.0;
    double dropped_area = 0.0;
    // Pieces narrower than min_width on average but with a part wider than
    // 2 kWideRegionFactor min_width: kept (they are regions of the face).
    int kept_wide = 0;
    bool changed() const { return reoriented || crossings > 0 || dropped > 0; }
};

// The coedges' polylines (in loop order, each in its traversal direction) joined
// into one closed polygon: a coedge's first point is dropped when it lies within
// snap_uv of the previous coedge's last one (the earlier point is kept, so a
// shared edge's vertex stays); larger gaps are bridged by the closing segment
// between them and reported in max_gap; the last point is dropped if it closes
// onto the first. Orientation is not changed here.
TrimPolygon join_trim_loop(const std::vector<TrimPolyline>& coedges, bool outer, double snap_uv,
                           LoopRepairReport* report = nullptr);

// Simple polygons covering the loop: consecutive points within snap_uv merged;
// the loop reversed if its signed area disagrees with loop.outer; every
// crossing, touching or overlapping pair of segments cut at the shared point;
// the polygon split at points it visits twice; slivers (area <= snap_uv ·
// perimeter / 2, fewer than 3 points) dropped; each piece oriented for its role
// (a figure-eight outer loop gives two counter-clockwise loops). Segment pairs
// are found by a sweep over u (sorted by min u), so near-linear for typical loops.
// face_reversed: face.h (and the readers) mirror the loops of a reversed face
// (outer clockwise); such input is expected, so `reoriented` is only recorded
// when the loop disagrees with that convention. The output is always outer
// counter-clockwise, holes clockwise.
// surface, min_width (model units): when the loop crossed itself, pieces narrower than
// min_width on the surface (twice their area over their perimeter) are dropped too: a trim curve running
// back along the face's own boundary (a cut tangent to a seam) leaves zero-width
// lobes whose sides belong to two different neighbours, which then meet directly.
// Such a piece is kept when a point inside it lies farther than kWideRegionFactor
// min_width from its boundary (report->kept_wide); the width and area of what is
// dropped go to report->dropped_width and dropped_area.
// `deadline`: checked in the sweep, the split and the sliver tests; throws
// mesh::DeadlineExceeded once it has passed.
std::vector<TrimPolygon> repair_trim_loop(const TrimPolygon& loop, double snap_uv,
                                          LoopRepairReport* report = nullptr,
                                          bool face_reversed = false,
                                          const geom::NurbsSurface* surface = nullptr,
                                          double min_width = 0.0, mesh::Deadline* deadline = nullptr);

// Signed area in (u,v) of the polygon closed from back() to front()
// (positive: counter-clockwise).
double signed_area(const std::vector<PolylinePoint>& points);

}  // namespace trimkit::tess
