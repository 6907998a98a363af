// A face's trim loops from its boundary as a file gives it, for the readers of B-rep
// files (IGES, STEP's own reader): each boundary segment has model-space
// curves and/or parameter-space curves. The loops end up in the NURBS surface's (u,v)
// domain: parameter curves mapped from the surface's native parameters when the file
// has them and they agree with the model-space curve, else the model-space curve
// projected onto the surface (refined until the surface along it follows the curve,
// geom/project_curve_adaptive.h). Projected curves along a seam are put on the side
// the loop needs; on surfaces closed in u or v the loops are unwrapped and the surface
// extended over them (io/closed_surface_loops.h).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "geom/face.h"

namespace trimkit::io {

// 3D points along a face's boundary (sizes unbounded surfaces; sets the projection's tolerance).
using BoundaryHint = std::vector<Eigen::Vector3d>;

// One piece of a boundary as the file gives it: model-space curves (in the
// face's local space, in traversal order) and/or parameter-space curves (native
// parameters, in the file's order and direction).
struct BoundarySegment {
    std::vector<geom::NurbsCurve3d> model;
    std::vector<geom::NurbsCurve2d> param;
    bool prefer_model = false;  // IGES 142 preference 2: model-space curve preferred
    bool prefer_param = false;  // IGES 142 preference 1: parameter curve preferred
    int edge = -1;              // first Model::edges index of this segment's pieces
    bool edge_reversed = false;
};

// What the loops need to know of the file and the surface.
struct FaceLoopsContext {
    // Distance below which the surface's boundary rows count as one (closed direction).
    double closure_tolerance = 0.0;
    // The file's resolution (IGES Global field 19), 0 when not given: parameter curves
    // this close to their model-space curve agree.
    double resolution = 0.0;
    // A parameter curve in the surface's native parameters mapped into the NURBS (u,v);
    // nullopt when there is no usable map. Empty: parameter curves are not used.
    std::function<std::optional<geom::NurbsCurve2d>(const geom::NurbsCurve2d&)> map_to_nurbs;
};

// Distance below which a surface's boundary rows count as one (a closed direction):
// 1e-7 of its size (above file rounding, below real gaps, as SurfaceProjector's seam
// test), or the file's resolution (0: none) when larger, counted up to 1e-4 of the
// size (an absurd resolution does not close a surface with a visible gap).
double closure_tolerance(const geom::NurbsSurface& s, double resolution);

// The chain run backwards: curves in reverse order, each reversed.
std::vector<geom::NurbsCurve3d> reversed_chain(const std::vector<geom::NurbsCurve3d>& c);

// Appends the curves' control points to the hint.
void add_points(BoundaryHint* hint, const std::vector<geom::NurbsCurve3d>& curves);

// face.surface = S and face.loops from the segments (a natural outer loop first when
// `natural_outer`; loop 1 flagged outer when `first_is_outer`), on surfaces closed in u
// or v unwrapped and covered. Model-space trims are projected adaptively; where that
// rounds a near-pole end of the surface the loops are built again from project_curve's
// samples, with a warning. Warnings go to face.warnings.
void build_face_loops(const geom::NurbsSurface& S, const FaceLoopsContext& context, const BoundaryHint& hint,
                      const std::vector<std::vector<BoundarySegment>>& loops, bool natural_outer,
                      bool first_is_outer, geom::Face& face);

// True when the face is the whole of a surface without boundary less holes: S is
// closed in u or v and, in the other direction, closed too or pinched to a pole at
// both ends (a ball, a torus, a surface of revolution from pole to pole), and every
// loop of `face` (as build_face_loops made them from S, in the file's directions)
// closes in (u,v) and runs as a hole: clockwise, counter-clockwise on a reversed
// face. STEP gives such a face (a ball drilled three times) its holes and no outer bound.
bool holes_of_whole_surface(const geom::NurbsSurface& S, const geom::Face& face);

// Loop 1, which the file declares outer, unless another loop encloses it
// (enclosing_loop); `what` is the file's word for a loop in the warning.
void settle_outer_loop(geom::Face& face, const std::string& what);

// Closes each loop (close_loop: snaps and bridges gaps, reorders pieces; a loop with no
// usable curve is dropped, an outer one replaced by the natural boundary), puts the
// outer loop first and orients the loops as face.h fixes.
void close_face_loops(geom::Face& face);

}  // namespace trimkit::io
