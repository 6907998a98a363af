// The B-rep data model below Model: Edge (shared 3D curve), Coedge (a 2D trim
// curve in a face's (u,v) domain, optionally using an Edge), Loop (closed chain
// of coedges) and Face (a NurbsSurface bounded by loops). Conventions: the outer
// loop comes first and runs counter-clockwise in (u,v), holes clockwise, when the
// face is not reversed; `reversed` flips the face's normal relative to Su x Sv.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geom/nurbs_curve.h"
#include "geom/nurbs_surface.h"

namespace trimkit::geom {

// An edge of a B-rep shared by the faces it bounds. Both faces' coedges refer
// to it by index into Model::edges, so tessellation can approximate it once.
struct Edge {
    std::optional<NurbsCurve3d> curve;  // model-space curve, absent if unknown
    std::optional<Eigen::Vector3d> start, end;  // end vertices, where known
};

struct Coedge {
    NurbsCurve2d curve;        // in the face's (u,v) domain, traversal direction
    int edge = -1;             // index into Model::edges, -1 if not shared
    bool edge_reversed = false;  // traverses the edge against its curve direction
};

struct Loop {
    std::vector<Coedge> coedges;  // end of each meets start of the next
    bool outer = false;
};

struct Face {
    NurbsSurface surface;
    std::vector<Loop> loops;    // never empty: untrimmed faces get their natural boundary
    bool reversed = false;
    // What the file called the surface before conversion to NURBS: "bspline",
    // "plane", "cylinder", "cone", "sphere", "torus", "revolution",
    // "tabulated_cylinder", "ruled", ... (reported by `trimkit info`).
    std::string surface_kind = "bspline";
    std::string name;
    int color = -1;             // index into Model::colors, -1 for none
    int source_entity = 0;      // IGES directory sequence number (or 0)
    std::vector<std::string> warnings;  // e.g. "trim curve 2 projected from model space"
};

// The natural boundary of a surface's domain as one counter-clockwise loop of
// four line coedges.
Loop natural_boundary_loop(const NurbsSurface& surface);

// The counter-clockwise loop of four line coedges around [u0, u1] x [v0, v1].
Loop rectangle_loop(double u0, double u1, double v0, double v1);

}  // namespace trimkit::geom
