// SurfaceProjector: point inversion on a NurbsSurface (closest (u,v) to a
// model-space point) and the parameter-space image of a model-space curve, for
// trim curves given only in model space. Coarse grid start, then Newton on
// |S(u,v) - x|² [PT] Sec. 6.1 (eq. 6.5-6.7), clamped to the domain; on closed
// directions and at poles the previous point of a curve decides the seam side.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "geom/nurbs_curve.h"
#include "geom/nurbs_surface.h"

namespace trimkit::geom {

// Feet of a point closer than this fraction of the surface's size to each other in
// distance are equally good: continuity with the previous point decides.
constexpr double kSameFoot = 1e-6;

// True where parameter d (0: u, 1: v) of `s` is free at uv: a whole domain of it moves
// the surface point by less than kSameFoot of `size` (at or a hair off a pole).
bool parameter_is_free(const NurbsSurface& s, const Eigen::Vector2d& uv, int d, double size);

class SurfaceProjector {
public:
    explicit SurfaceProjector(const NurbsSurface& surface);

    // (u,v) of the closest surface point to x. With `near`, Newton also starts
    // from it, and a seam or pole keeps the side / the u (or v) of `near`.
    Eigen::Vector2d invert(const Eigen::Vector3d& x, const Eigen::Vector2d* near = nullptr) const;

    // parameter_is_free on this surface, with its sampled size.
    bool free_at(const Eigen::Vector2d& uv, int d) const { return parameter_is_free(s_, uv, d, size_); }

    bool closed_u() const { return closed_u_; }
    bool closed_v() const { return closed_v_; }
    const NurbsSurface& surface() const { return s_; }
    double size() const { return size_; }

private:
    Eigen::Vector2d newton(const Eigen::Vector3d& x, Eigen::Vector2d uv) const;
    void mark_poles();
    Eigen::Vector2d grid_uv(int k) const;  // (u,v) of grid sample k
    bool grid_neighbours(int a, int b) const;  // samples a and b at most one step apart
    // invert's foot uv (distance du from x) settled against `near`: continuity, seam side, pole.
    Eigen::Vector2d settled(const Eigen::Vector3d& x, Eigen::Vector2d uv, double du, const Eigen::Vector2d* near) const;

    const NurbsSurface& s_;
    double u0_, u1_, v0_, v1_;
    int nu_, nv_;
    std::vector<Eigen::Vector3d> grid_;  // nu_ x nv_ samples, v fastest
    std::vector<char> at_pole_;          // grid samples on a row or column that is one point
    bool closed_u_ = false, closed_v_ = false;
    double size_ = 1;
};

// The parameter-space curve of model-space curve `c` on the projector's surface:
// exact (control points mapped) when the surface is an affine parallelogram,
// else points sampled along c, inverted, and joined by a degree-1 curve on c's
// parameters. `max_distance` (optional) receives the largest distance between
// c's samples and the surface.
NurbsCurve2d project_curve(const SurfaceProjector& projector, const NurbsCurve3d& c,
                                 double* max_distance = nullptr);

}  // namespace trimkit::geom
