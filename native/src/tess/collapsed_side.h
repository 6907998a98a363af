// Sides of a surface's domain that the surface collapses to one point (a cone's
// apex, a sphere's pole). A cell touching such a side, triangulated in (u,v), may get
// a fan from the side's vertices that folds in 3D: the whole side is one point, so a
// triangle from it is right only where the rest of the cell is monotone in the free
// parameter, which a trim dipping into the cell breaks (cone_with_apex_faces.igs: a
// backward triangle of area 11.8 beside a hole). In polar coordinates about the side,
// the side is one point as in 3D, and the same ear clipping gives no fold.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "geom/nurbs_surface.h"

namespace trimkit::tess {

// Domain sides in the order u = u0, u = u1, v = v0, v = v1.
using CollapsedSides = std::array<bool, 4>;

// Sides along which the surface point does not move (geom::parameter_is_free at
// three points of the side).
CollapsedSides collapsed_sides(const geom::NurbsSurface& s);

// The first collapsed side that a vertex of `ring` lies on (within 1e-9 of the
// domain's extent), or -1.
int touched_collapsed_side(const geom::NurbsSurface& s, const CollapsedSides& sides,
                           const std::vector<Eigen::Vector2d>& uv, const std::vector<int>& ring);

// Every point of `uv` in polar coordinates about `side`: radius the distance in the
// collapsing parameter from the side, angle the other parameter scaled so its whole
// domain spans a quarter turn. The map keeps orientation, so counter-clockwise rings
// stay counter-clockwise.
std::vector<Eigen::Vector2d> polar_about_side(const geom::NurbsSurface& s, int side,
                                              const std::vector<Eigen::Vector2d>& uv);

}  // namespace trimkit::tess
