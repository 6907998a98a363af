// ParameterMap: the map from a surface's native parameters (s, t), in which a
// reader's trim curves are written (OCCT's or IGES's angles and lengths), to the
// (u, v) of the NurbsSurface built for it. Each axis is affine, x' = scale·x +
// offset, optionally followed by an ArcParameterMap (angle -> NURBS parameter of
// the rational arcs of an analytic surface); `swap` exchanges s and t first.
#pragma once

#include <optional>

#include <Eigen/Core>

#include "geom/arc_parameter_map.h"
#include "geom/nurbs_curve.h"

namespace trimkit::geom {

struct AxisMap {
    double scale = 1.0, offset = 0.0;
    std::optional<ArcParameterMap> arc;  // applied after the affine part
    // > 0 for a surface wound several times (a thread's face spans more than one turn):
    // x beyond arc's range by k periods maps as arc.to_nurbs(x - k period) + k period.
    double period = 0.0;

    double apply(double x) const;
    bool affine() const { return !arc.has_value(); }
};

struct ParameterMap {
    bool swap = false;  // (s, t) -> (t, s) before the axis maps
    // The NURBS's Su x Sv against the file's surface normal: exchanging u and v turns it
    // around (a face on the surface is reversed with it, and its loops' sense in (u,v)).
    bool flips_normal() const { return swap; }
    AxisMap u, v;

    Eigen::Vector2d apply(Eigen::Vector2d st) const;
    bool affine() const { return u.affine() && v.affine(); }
    bool identity() const;

    // The curve c(τ) of (s, t) mapped to (u, v): exact (control points mapped, τ
    // kept) when the map is affine; the same trace (points mapped) when c is a
    // polyline of axis-parallel segments; otherwise the
    // cubic refit_mapped_curve within `tolerance` in (u, v), with C0 knots where c
    // crosses an arc's knot angles (the map is only C1 there).
    NurbsCurve2d map_curve(const NurbsCurve2d& c, double tolerance) const;
};

}  // namespace trimkit::geom
