// Test models built with Open CASCADE and written as STEP or .brep files, so that the
// readers are tested on shapes whose exact areas and placements the tests derive.
// Compiled into io_tests only when trimkit is built with OCCT (TRIMKIT_WITH_OCCT).
#pragma once

#include <string>
#include <vector>

#include <Eigen/Core>

namespace trimkit::test {

// A plate [0, L] x [0, W] x [0, H] with through holes of radius r along z at `centres`,
// as an AP214 STEP solid.
void write_plate_with_holes_step(const std::string& path, double L, double W, double H,
                                 const std::vector<Eigen::Vector2d>& centres, double r);

// One face of the cylinder of radius R about z, z in [0, h], over the angle range
// [u0, u1] (natural bounds, e.g. [-π/2, π/2]: the face crosses the seam at u = 0),
// as a .brep file.
void write_cylinder_face_brep(const std::string& path, double R, double h, double u0, double u1);

// A helical strip on the cylinder of radius R about z, as a thread's face: in (u, v)
// the parallelogram between v = k u and v = k u + w for u in [0, sweep] (sweep may
// exceed 2π: the face winds round more than once), edges built on the surface and
// their 3D curves from the p-curves (BRepLib::BuildCurves3d), as a .brep file.
void write_helical_strip_brep(const std::string& path, double R, double k, double w, double sweep);

// The cylinder face over [0, π/2] x [0, h] built edge by edge, one of whose p-curves
// is damaged: `gap` > 0 shifts the p-curve of the bottom arc by gap in v (its ends no
// longer meet the neighbours' in (u,v)); gap == 0 leaves that edge without a p-curve.
// The vertices get `vertex_tolerance`.
void write_damaged_cylinder_face_brep(const std::string& path, double R, double h, double gap,
                                      double vertex_tolerance = 1e-7);

// A planar B-spline face: the bilinear surface S(u, v) = (L u, L v, 0) on [0, 1]^2,
// trimmed by the square [-m, 1 + m]^2 in (u, v), past the surface's domain by m on
// every side (as real files trim B-splines slightly outside their domain), as .brep.
void write_bspline_face_past_domain_brep(const std::string& path, double L, double m);

// The square [0, L]^2 (z = 0) as a B-spline face x = L u^2, y = L v over [0, 1]^2,
// whose parametrization hardly moves along u near u = 0: the bottom edge's p-curve
// starts at (gap, 0) while the left edge's ends at (0, 0), a (u,v) gap of `gap` but
// a 3D gap of L gap^2 (inside the vertex's tolerance), as Bottom.brep's blend corner.
void write_slow_corner_face_brep(const std::string& path, double L, double gap);

// An assembly "pair" of one part "block" (box dx x dy x dz at the origin) placed twice,
// translated by t1 and by t2 (the second also turned by 90° about z), as STEP (XCAF).
void write_box_assembly_step(const std::string& path, double dx, double dy, double dz,
                             const Eigen::Vector3d& t1, const Eigen::Vector3d& t2);

// An assembly "top" holding the sub-assembly "pair" twice: at translation s1, and
// turned by 90° about x, then moved by s2; "pair" holds the part "block" (box dx x dy x dz
// at the origin) translated by t1 and by t2, as STEP (XCAF).
void write_nested_box_assembly_step(const std::string& path, double dx, double dy, double dz,
                                    const Eigen::Vector3d& t1, const Eigen::Vector3d& t2,
                                    const Eigen::Vector3d& s1, const Eigen::Vector3d& s2);

// `levels` assemblies, each holding the one below twice (unmoved and moved by 2^(k+1)
// along x), over a unit box: 2^levels occurrences of one part, as STEP (XCAF).
void write_doubling_assembly_step(const std::string& path, int levels);

// Solids written by OCCT's IGES writer in B-rep mode (186/514/510/508 on 192/196
// surfaces with form 1): each returns the solid's area by OCCT's BRepGProp, the
// independent measure the tests compare trimkit's mesh with. A path ending in .stp or
// .step gets the solid as STEP (OCCT's AP214 writer) instead, whatever the mode.
// A cylinder of radius R about z, z in [0, h], pierced by a cross hole of radius r
// along x at z = h/2: one hole lies on the seam (u = 0), so the lateral face's outer
// loop runs round that hole and OCCT's writer flags the other hole as the outer loop.
double write_cylinder_cross_hole_iges(const std::string& path, double R, double h, double r);
// A sphere of radius R about the origin without the box x > c, y > c, pierced near its
// north pole by a hole of radius r along z at (a, 0): the sphere face's loops, unwrapped
// from their own starts, sit a period apart in u.
double write_sphere_cut_near_pole_iges(const std::string& path, double R, double c, double a, double r);

// A ball of radius R about the origin pierced from its centre by a cylinder of radius r
// along (1, 0, 0.6): the hole lies on the sphere's seam (u = 0), whose edge splits its
// circle into two halves, one each side of the seam. IGES B-rep mode (186...) or faces
// mode (144/142, the sphere as a surface of revolution). Returns BRepGProp's area.
double write_ball_hole_on_seam_iges(const std::string& path, double R, double r, bool brep_mode);

// An a x b x c box with every edge rounded to radius r: its corners are sphere
// octants, some of them bounded by the sphere's seam down to its pole. B-rep mode
// (IGES 186..., or STEP for a .stp path). Returns BRepGProp's area.
double write_rounded_box(const std::string& path, double a, double b, double c, double r);

// A 50 x 40 x 30 box rounded to radius 5, its faces moved apart by up to 1e-4 and sewn
// again at 1e-3 (BRepBuilderAPI_Sewing): the corner octants' meridians lie 3e-5 off
// their sphere's seam. B-rep mode (STEP for a .stp path). Returns BRepGProp's area.
double write_sewn_rounded_box(const std::string& path);

// The faces of a 50 x 40 x 30 box rounded to radius 5, each copied on its own (edges
// and vertices of its own, as Spatial writes a SHELL_BASED_SURFACE_MODEL) and put in
// one shell unsewn; STEP (AP214) for a .stp path, else .brep. Returns BRepGProp's area.
double write_loose_face_rounded_box(const std::string& path);
// A ball of radius R about the origin pierced from its centre by `holes` cylinders of
// radius r along (cos a, sin a, 0.6), a = 2 pi i / holes (the first on the seam, which
// it cuts in two), then turned 0.7 rad about (1, 1, 0). B-rep mode (IGES 186..., or
// STEP for a .stp path). Returns BRepGProp's area.
double write_perforated_ball(const std::string& path, double R, double r, int holes);

// A whole ball of radius R (BRepPrimAPI_MakeSphere): one face whose only loop is
// its seam edge, down one side and up the other. IGES B-rep or faces mode.
// Returns BRepGProp's area.
double write_whole_ball_iges(const std::string& path, double R, bool brep_mode);

// A cone of base radius R and height h (apex up) pierced across by a cylinder of
// radius r along x at y = 4 R / 15, z = 0.3 h, as IGES faces mode (144: the cone a
// surface of revolution whose domain side u = 0 is the apex) or B-rep mode (a 194
// cone sized by its boundary). Returns BRepGProp's area.
double write_cone_apex_hole_iges(const std::string& path, double R, double h, double r, bool brep_mode);

// A block 80 x 40 x 20 with through holes of radius 8 and 6 whose rims are filleted
// with radius 2 (quarter tubes of tori bounded by the iso-line where two of the torus's
// Bezier patches meet), as IGES B-rep mode. Returns BRepGProp's area.
double write_filleted_hole_block_iges(const std::string& path, bool brep_mode = true);

// One face: the circle of radius 10 about (30, 0, 0) in the xz plane revolved about z
// (a Geom_SurfaceOfRevolution) over 3pi/2 and the circle's parameters [theta0, theta1]
// (OCCT's own: 3pi/2..2pi is the upper outer quarter), drilled with radius 3 through
// its middle, obliquely (a loop that is no iso-curve). IGES faces mode: a 120 whose
// generatrix is a 100 arc. Returns BRepGProp's area.
double write_revolved_arc_hole_iges(const std::string& path, double theta0, double theta1);

// A torus of radii 40 and 12 pierced radially by a cylinder of radius 4 where its two
// seams meet ((52, 0, 0)), as IGES B-rep mode: the reader extends the torus past its
// seam, and the loop runs along the extended surface's knot lines. Returns
// BRepGProp's area.
double write_torus_hole_on_seams_iges(const std::string& path);

// A frustum (radii 25 and 12, height 40) with a cross hole of radius 5 along x at
// z = 20, through its seam, as IGES B-rep mode. Returns BRepGProp's area.
double write_frustum_hole_on_seam_iges(const std::string& path);

// A prism of height h over the closed periodic B-spline interpolating `outline` (z = 0),
// as .brep: the plane faces carry no stored p-curves, so OCCT makes them from the
// periodic 3D curve. Returns the solid's area from the outline's samples (BRepGProp
// is off on this solid).
double write_periodic_spline_prism_brep(const std::string& path, const std::vector<Eigen::Vector2d>& outline,
                                        double h);

}  // namespace trimkit::test
