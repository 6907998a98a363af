// Exact error of the cells of a surface of revolution whose meridian is a straight
// line (cylinder, cone, plane annulus) or a circular arc (sphere, torus): the
// analytic replacement of bilinear_error for faces whose kind says so. The surface
// is S = R_phi(a) C(b): a turns the meridian C about the axis. Distances are in
// model units, split parameters local to the patch as in bilinear_error.
//
// Measure: the distance from a mesh point to the surface (the guarantee of DESIGN.md,
// what `trimkit check` measures), not |P - S| at the mesh point's own (u,v): the
// circle's rational parameterisation moves points along the circle, which costs
// nothing geometrically but would be counted by the (u,v) measure.
#pragma once

#include <optional>
#include <string>

#include <Eigen/Core>

#include "geom/nurbs_surface.h"
#include "tess/bezier_patch.h"
#include "tess/bilinear_error.h"

namespace trimkit::tess {

struct RevolutionShape {
    int angle_dir = 0;                 // 0: u turns about the axis, 1: v does
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();  // a point of the axis
    Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();   // unit
    bool circle_meridian = false;      // false: straight meridian
    // Meridian circle in (rho, z) = (distance from the axis, height along it).
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    double radius = 0.0;
    // Added to every bound: the misfit the recognition accepts (kShapeFitTolerance
    // times the surface's size plus its largest coordinate; with the weight misfit
    // of a control-net proof, revolution_error.cpp).
    double slack = 0.0;

    // (rho, z) of a point.
    Eigen::Vector2d meridian(const Eigen::Vector3d& P) const;
};

// Relative misfit (to the control box's diagonal plus the largest coordinate) up to
// which points are taken to lie on the recognised shape: above the rounding of
// coordinates printed to 10 digits in IGES files (hammer.iges: 1.7e-5 at 2e4),
// far below any tolerance a user asks for.
constexpr double kShapeFitTolerance = 1e-8;

// The shape of `S`, or empty:
//  - any rational S whose control net proves it (revolution_error.cpp: every row of
//    every Bezier patch a degree-2 circular arc about one axis with separable weights,
//    the meridian's control points collinear or a circular arc), within
//    kShapeFitTolerance; B-spline faces of CAD files are often exact cylinders or tori;
//  - else, when `kind` (geom::Face::surface_kind) is "cylinder", "cone", "sphere",
//    "torus" or "revolution", samples of S: rows in one direction are circles about one
//    axis and the meridian is a line or a circle. The kind promises an exact
//    construction (geom/analytic_surfaces.h, io/occt_geometry.cpp); the samples only
//    find its axis and reject a surface a transform has deformed.
std::optional<RevolutionShape> revolution_shape(const geom::NurbsSurface& S, const std::string& kind);

// Bound on the distance to S of any point of a triangle whose vertices are points
// of S over the cell `patch` (a piece of one Bezier patch of S), and the same for
// the distance of every point of S over the cell to the cell's triangles:
//   e = rho_max (1 - cos(theta / 2)) + r (1 - cos(psi / 2)) + slack
// theta: the cell's angle about the axis, rho_max: its largest distance from the
// axis, r, psi: the meridian circle's radius and the cell's angle on it (0 for a
// straight meridian). The sagitta r (1 - cos(theta/2)) of a chord over an arc theta,
// [PT] Sec. 7.5 / any text on circle chords; the sum is derived in the .cpp.
// Split: across the term that is larger, at the parameter where the angle reaches
// floor(k/2)/k of it, k the pieces that bring the term within `tolerance`.
// Returns an infinite bound when the cell is not one the derivation covers (an
// angle >= kMaxCellAngle, a meridian line crossing the axis inside the cell).
constexpr double kMaxCellAngle = 2.0;  // radians, below pi with room for rounding
BilinearError revolution_error(const RevolutionShape& shape, const BezierPatch& patch, double tolerance);

}  // namespace trimkit::tess
