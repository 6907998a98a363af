// Exact rational NURBS forms of analytic surfaces for readers. The u and v domains
// are the entity's native parameter ranges: angles in radians (the NURBS
// parameter equals the angle at every knot; ArcParameterMap gives the exact map
// in between), lengths affinely. Angular ranges must increase (θ0 < θ1, sweep
// <= 2π). Frames: A = axis normalised, X = ref_dir made orthogonal to A and
// normalised, Y = A × X; angles turn from X towards Y (right-hand rule about A).
// For cylinders, cones, spheres and tori Su × Sv points away from the axis.
#pragma once

#include <Eigen/Core>

#include "geom/nurbs_curve.h"
#include "geom/nurbs_surface.h"

namespace trimkit::geom {

// ---- Elementary surfaces ------------------------------------------------------------

// S(u, v) = origin + u·u_dir + v·v_dir on [u0, u1] × [v0, v1]; bilinear, degree (1, 1).
// Throws InvalidInput if u_dir and v_dir are parallel or zero, or a range is empty.
NurbsSurface plane_patch(const Eigen::Vector3d& origin, const Eigen::Vector3d& u_dir,
                         const Eigen::Vector3d& v_dir, double u0, double u1, double v0,
                         double v1);

// S(θ, z) = origin + z·A + radius (cos θ X + sin θ Y), θ ∈ [θ0, θ1], z ∈ [z0, z1].
// Degree (2, 1). [PT] Sec. 8.3 (a circle translated along A).
NurbsSurface cylinder_patch(const Eigen::Vector3d& origin, const Eigen::Vector3d& axis,
                            const Eigen::Vector3d& ref_dir, double radius, double theta0,
                            double theta1, double z0, double z1);

// S(θ, v) = origin + v·A + ρ(v) (cos θ X + sin θ Y), ρ(v) = radius_at_origin +
// v·tan(semi_angle); v is the distance along A (negative ρ: the other nappe).
// |semi_angle| < π/2, radius_at_origin >= 0. Degree (2, 1).
NurbsSurface cone_patch(const Eigen::Vector3d& origin, const Eigen::Vector3d& axis,
                        const Eigen::Vector3d& ref_dir, double radius_at_origin,
                        double semi_angle, double theta0, double theta1, double v0,
                        double v1);

// S(θ, φ) = center + r (cos φ (cos θ X + sin θ Y) + sin φ A): θ longitude,
// φ latitude with -π/2 <= φ0 < φ1 <= π/2. Degree (2, 2). [PT] Sec. 8.5, the
// tensor product of two ArcParameterMap arcs.
NurbsSurface sphere_patch(const Eigen::Vector3d& center, const Eigen::Vector3d& axis,
                          const Eigen::Vector3d& ref_dir, double radius, double theta0,
                          double theta1, double phi0, double phi1);

// S(θ, φ) = center + (R + r cos φ)(cos θ X + sin θ Y) + r sin φ A: θ around the
// axis, φ around the tube (φ = 0 on the outer equator). R > 0, r > 0 (R < r, a
// spindle torus, is allowed). Degree (2, 2).
NurbsSurface torus_patch(const Eigen::Vector3d& center, const Eigen::Vector3d& axis,
                         const Eigen::Vector3d& ref_dir, double major_radius,
                         double minor_radius, double theta0, double theta1, double phi0,
                         double phi1);

// ---- Swept surfaces ------------------------------------------------------------------

// The generatrix turned about the axis through axis_point along axis_dir by the
// angle v ∈ [θ0, θ1] (right-hand rule about axis_dir; v = 0 is the generatrix
// itself); u is the generatrix parameter (its knots kept). Degree (p, 2).
// [PT] Sec. 8.5, Algorithm A8.1 with ArcParameterMap segments.
NurbsSurface surface_of_revolution(const NurbsCurve3d& generatrix,
                                   const Eigen::Vector3d& axis_point,
                                   const Eigen::Vector3d& axis_dir, double theta0,
                                   double theta1);

// S(u, v) = C(u) + v·translation, u the directrix parameter, v ∈ [v0, v1].
// Degree (p, 1). [PT] Sec. 8.3. Throws InvalidInput for a zero translation.
NurbsSurface tabulated_cylinder(const NurbsCurve3d& directrix, const Eigen::Vector3d& translation,
                                double v0 = 0.0, double v1 = 1.0);

// S(u, v) = (1 - v) c1(s1(u)) + v c2(s2(u)), u, v ∈ [0, 1], s1, s2 the affine maps
// of [0, 1] onto the curves' domains (IGES 118 form 1, equal relative parameter).
// The curves are made compatible (make_compatible) and, if their weights differ,
// given one denominator (make_compatible_weights) so v is exactly the fraction
// along each ruling. [PT] Sec. 8.4.
NurbsSurface ruled_surface(const NurbsCurve3d& c1, const NurbsCurve3d& c2);

}  // namespace trimkit::geom
