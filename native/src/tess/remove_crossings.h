// Cell crossings removed where the triangles that replace them keep the bound.
// trim_cells adds a vertex wherever a trim chord crosses a cell side. It lies on the
// chord (in (u,v) and in 3D), so the face's boundary keeps its shape without it, but
// it is one more boundary point for this face and, through close_t_junctions, for the
// face beside it (linkrods.step at 1e-3: 2207 trim points, 2876 boundary edges on its
// B-spline faces). A crossing c between its trim neighbours a and b is removed by
// triangulating its fan again without it; the new triangles are kept only when each
//  - runs counter-clockwise in (u,v) and faces along Su x Sv in 3D;
//  - is within the bound kd_subdivision gives its cells: over its own (u,v) box, the
//    smaller of (M_uu du^2 + 2 M_uv du dv + M_vv dv^2) / 8 (block_error.h, S C^1 inside
//    the box) and, in one Bezier patch, the cell bound of the patch's piece over the box
//    (revolution_error with a `shape`, else bilinear_error in `mode`) is
//    <= interior_tolerance, and that plus the largest offset of its vertices from S
//    (|x - S(uv)|, computed) <= total_tolerance (tessellation_options.h's shares).
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "geom/nurbs_surface.h"
#include "mesh/deadline.h"
#include "tess/revolution_error.h"
#include "tess/tessellation_options.h"

namespace trimkit::tess {

struct CrossingMesh {
    std::vector<Eigen::Vector2d> uv;
    std::vector<Eigen::Vector3d> xyz;               // 3D points, at least of a crossing's triangles
    std::vector<char> crossing;                     // per vertex: may be removed
    std::vector<std::array<int, 3>> triangles;      // counter-clockwise in (u,v)
    std::vector<std::array<int, 2>> trim_edges;     // directed, the face on their left
};

// Removes the crossings it can from `mesh` (triangles and trim edges rewritten; the
// vertex arrays keep their entries). Returns how many it removed.
// `deadline`: checked per crossing; throws mesh::DeadlineExceeded.
int remove_crossings(const geom::NurbsSurface& S, const RevolutionShape* shape, ErrorMode mode, CrossingMesh& mesh,
                     double interior_tolerance, double total_tolerance, mesh::Deadline* deadline = nullptr);

}  // namespace trimkit::tess
