// Least-squares B-spline surface fitting with constraints: a non-rational, clamped,
// uniform-knot surface on [0, 1]² approximating points at given (u, v), with
//  - fixed control points (the boundary rows of [Muraki] Sec. 4.1's four curves),
//  - tangent-plane rows n·S_u = 0, n·S_v = 0 at given (u, v): the surface's tangent
//    plane there is the plane of normal n (G1 to a neighbour, [Muraki] Sec. 4.2),
//  - the thin-plate smoothing term of smoothing_rows.h ([Muraki] Sec. 6, Fig. 17).
// Control points: count_u x count_v, row-major with v fastest (NurbsSurface's order).
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "geom/nurbs_surface.h"

namespace trimkit::fit {

struct SurfaceSample {
    Eigen::Vector2d uv;
    Eigen::Vector3d x;
    double weight = 1.0;
};

struct TangentPlaneSample {
    Eigen::Vector2d uv;
    Eigen::Vector3d normal;  // unit
    double weight = 1.0;
};

struct SurfaceFitProblem {
    int degree_u = 3, degree_v = 3;
    int count_u = 4, count_v = 4;  // degree + 1 .. kMaxFitControlPoints each
    std::vector<SurfaceSample> points;
    std::vector<TangentPlaneSample> tangent_planes;
    // Empty, or count_u * count_v entries; a given entry fixes that control point.
    std::vector<std::optional<Eigen::Vector3d>> fixed;
    double smoothing = 1e-6;        // energy weight against the mean squared point error
    double tangent_weight = 100.0;  // tangent rows' weight against the points'
};

// Objective: Σ w_k |S(u_k,v_k) - x_k|² / Σ w_k + tangent_weight Σ w_t ((n·S_u)² +
// (n·S_v)²) / Σ w_t + smoothing E(P) / #energy rows, over the free control points.
// Throws geom::InvalidInput for bad degrees, counts, sizes, non-finite values or
// (u, v) outside [0, 1]²; geom::NumericalFailure when the free points are not
// determined.
geom::NurbsSurface fit_surface(const SurfaceFitProblem& problem);

}  // namespace trimkit::fit
