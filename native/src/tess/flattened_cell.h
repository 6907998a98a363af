// Cells whose (u,v) triangulation flips in 3D. A triangle that is thin in (u,v) can
// face backwards in 3D: on a cone whose cell spans a whole ruling (ruled faces need no
// inner points), a triangle from the ruling's two ends to a hole point beside the
// (u,v) chord has its 3D corner on the other side of the 3D chord (the (u,v) line is
// a curve on the cone). frustum_hole_on_seam_brep.igs at 0.01 of its diagonal: two
// backward triangles of area 8.8 each, area 1.0028, within T both ways. Such a cell is
// triangulated again in the plane of its 3D points (the cell is flat within its bound)
// and the result kept when it has no backward triangle.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "geom/nurbs_surface.h"
#include "mesh/deadline.h"

namespace trimkit::tess {

// True if a triangle of `triangles` (indices into `xyz`, counter-clockwise in (u,v))
// faces against Su x Sv at its (u,v) centroid by more than `slack` of its area.
bool has_backward_triangle(const geom::NurbsSurface& s, const std::vector<Eigen::Vector2d>& uv,
                           const std::vector<Eigen::Vector3d>& xyz,
                           const std::vector<std::array<int, 3>>& triangles);

// The polygon (outer ring and holes, indices into uv / xyz) triangulated in the plane
// through its 3D points normal to Su x Sv at its (u,v) centre; empty if that has a
// backward triangle too. Indices of the result refer to uv / xyz.
std::vector<std::array<int, 3>> triangulate_in_3d_plane(const geom::NurbsSurface& s,
                                                        const std::vector<Eigen::Vector2d>& uv,
                                                        const std::vector<Eigen::Vector3d>& xyz,
                                                        const std::vector<int>& outer,
                                                        const std::vector<std::vector<int>>& holes,
                                                        mesh::Deadline* deadline);

}  // namespace trimkit::tess
