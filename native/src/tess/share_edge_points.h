// Watertight shared edges: an edge approximated once (on the first face that
// meets it) gives the second face its boundary points. For each 3D point of the
// edge the second face's coedge parameter t is found where S_B(c_B(t)) is
// closest, so uv = c_B(t) lies on B's trim curve while xyz stays the SAME 3D
// point; both faces' boundary vertices are then identical and weld exactly.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "geom/face.h"
#include "geom/nurbs_surface.h"
#include "tess/trim_polyline.h"

namespace trimkit::tess {

// The edge's 3D points in the direction of the EDGE (its curve's direction) from a
// face's polyline of a coedge on it: the polyline's xyz, reversed if the coedge
// traverses the edge against its direction (Coedge::edge_reversed).
std::vector<Eigen::Vector3d> edge_points_from(const TrimPolyline& polyline, bool edge_reversed);

struct SharedEdgePolyline {
    TrimPolyline polyline;  // in the coedge's traversal direction, edge = coedge.edge
    double max_gap = 0.0;   // largest |S_B(uv) - xyz|: the file's edge gap on this face
    std::vector<Eigen::Vector3d> feet;  // S_B(uv) of each edge point, in the edge points' order
};

// Face B's polyline for `coedge` (on surface S) through the given edge points (in
// the edge's direction, >= 2 of them). The coedge's ends take its domain ends
// exactly; interior points take t by a coarse search over samples of the curve
// (forward of the previous point's t, so the parameters are monotone along the
// coedge) refined by Newton's method on (Γ(t) - X)·Γ'(t) = 0, Γ = S∘c, clamped
// between the previous t and the domain end. The caller warns when max_gap
// exceeds the tolerance. Throws InvalidInput for fewer than 2 points.
SharedEdgePolyline share_edge_points(const geom::NurbsSurface& S, const geom::Coedge& coedge,
                                     const std::vector<Eigen::Vector3d>& edge_points);

// Edges whose two faces do not meet. A file may give an edge that lies on one face
// and farther than the tolerance from the other (bm2_ec_exhaust-A: 3.77 mm from four
// faces at T = 2.62 mm, within the file's own edge tolerance). A boundary both faces
// share cannot then lie on both surfaces; it lies within half their gap of each when
// every edge point is the mean of the first face's point and its foot on the second
// face (`feet`, from share_edge_points). The two end points stay: they are vertices
// that other edges and the faces' unshared trims meet.
void move_edge_points_midway(std::vector<Eigen::Vector3d>& edge_points, const std::vector<Eigen::Vector3d>& feet);

}  // namespace trimkit::tess
