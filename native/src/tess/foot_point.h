// Foot point: the (u,v) of the surface point closest to x, found by Newton's
// method on f(u,v) = |S(u,v) - x|² from a nearby start, [PT] Sec. 6.1 (eq. 6.5-6.7),
// with Gauss-Newton steps where the Hessian is not positive definite, clamped to
// the domain. Local: it finds the foot point in the basin of `start`
// (the caller supplies a good start, e.g. the interpolated (u,v) of a mesh point).
#pragma once

#include <Eigen/Core>

#include "geom/nurbs_surface.h"

namespace trimkit::tess {

// Newton stops when a step moves S by less than this fraction of the surface's
// size |Su|·Δu_domain + |Sv|·Δv_domain (1e-13: near double precision).
constexpr double kFootPointStep = 1e-13;
// Gauss-Newton steps from a far start take a few dozen iterations; Newton near
// the foot point converges in a handful.
constexpr int kFootPointIterations = 40;
// Step halvings tried before a step that does not lower |S - x| is given up
// (2^-30: below any useful step from a start in the right basin).
constexpr int kFootPointHalvings = 30;
// Damping of the 2x2 system, relative to its trace: keeps steps finite at
// poles (|Su| or |Sv| = 0) without changing them elsewhere.
constexpr double kFootPointDamping = 1e-12;

// The (u,v) found, never farther from x than `start` (clamped to the domain) is:
// each accepted step lowers the distance. Throws geom::NumericalFailure only if S cannot be evaluated at start.
Eigen::Vector2d foot_point(const geom::NurbsSurface& surface, const Eigen::Vector3d& x,
                           const Eigen::Vector2d& start);

}  // namespace trimkit::tess
