// Triangulation of one cell polygon in the (u,v) plane [Balazs] Sec. 7, shared by
// tess (cell polygons) and tbp (faces of a cut domain triangle). Indices
// refer to a shared array of (u,v) points; the outer ring runs counter-clockwise,
// holes clockwise. Triangles come out counter-clockwise in (u,v) and use only the
// polygon's own vertices (no Steiner points), so neighbouring cells stay conforming.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "mesh/deadline.h"

namespace trimkit::mesh {

// Convex polygons without holes: ear clipping without containment tests (linear
// time, the paper's convex case; collinear points on the sides stay vertices).
// Others: holes bridged to the outer ring (Eberly's visible-vertex bridge, the
// paper's "two half-edge pairs" per hole) and robust ear clipping: duplicated and
// touching vertices are skipped in containment tests, collinear vertices wait
// until they are ears, and when no proper ear remains, a degenerate (zero-area)
// triangle is emitted rather than a vertex dropped, so the mesh has no gaps.
// Consecutive duplicate indices are removed first; fewer than 3 vertices give none.
// deadline: checked while clipping ears (quadratic in the ring's length; a cell or a
// repaired trim loop piece can have 10^5 vertices); throws DeadlineExceeded.
std::vector<std::array<int, 3>> triangulate_polygon(const std::vector<Eigen::Vector2d>& uv,
                                                    const std::vector<int>& outer,
                                                    const std::vector<std::vector<int>>& holes = {},
                                                    Deadline* deadline = nullptr);

// True if the ring turns left or goes straight at every vertex.
bool is_convex(const std::vector<Eigen::Vector2d>& uv, const std::vector<int>& ring);

}  // namespace trimkit::mesh
