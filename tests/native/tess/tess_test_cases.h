// Shared trim-curve test cases for the tess tests: surfaces with trim curves on
// them, and a dense two-sided measure of a polyline's 3D deviation from S(c(t)).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "geom/analytic_curves.h"
#include "geom/analytic_surfaces.h"
#include "tess/trim_polyline.h"

namespace trimkit::test {

constexpr double kPi = 3.14159265358979323846;

struct TrimCase {
    std::string name;
    geom::NurbsSurface surface;
    geom::NurbsCurve2d curve;
};

// A circle of radius 0.8 around (π/2, 0) in (θ, φ) on the unit sphere patch
// θ in [0, π], φ in [-1.2, 1.2] (rational surface, rational trim).
inline TrimCase sphere_circle() {
    return {"sphere circle",
            geom::sphere_patch(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(),
                               Eigen::Vector3d::UnitX(), 1.0, 0.0, kPi, -1.2, 1.2),
            geom::to_2d(geom::circular_arc(Eigen::Vector3d(kPi / 2, 0, 0), Eigen::Vector3d::UnitX(),
                                           Eigen::Vector3d::UnitY(), 0.8, 0.0, 2 * kPi))};
}

// A bilinear patch with one corner pulled far out: (u,v) lengths near (1,1) are
// stretched ~10x relative to (0,0). Circle of radius 0.4 around (0.5, 0.5).
inline geom::NurbsSurface skewed_bilinear() {
    return geom::NurbsSurface(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2,
                              {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {8, 8, 3}});
}
inline TrimCase skewed_circle() {
    return {"skewed bilinear circle", skewed_bilinear(),
            geom::to_2d(geom::circular_arc(Eigen::Vector3d(0.5, 0.5, 0), Eigen::Vector3d::UnitX(),
                                           Eigen::Vector3d::UnitY(), 0.4, 0.0, 2 * kPi))};
}

// A straight uv line across a 270° cylinder patch (a helix piece in 3D).
inline TrimCase cylinder_line() {
    return {"cylinder line",
            geom::cylinder_patch(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(),
                                 Eigen::Vector3d::UnitX(), 1.0, 0.0, 1.5 * kPi, 0.0, 2.0),
            geom::line_segment(Eigen::Vector2d(0.1, 0.2), Eigen::Vector2d(4.5, 1.8))};
}

// [Yang] Sec. 4: the bicubic Bézier surface (rows of constant v, u along x) and
// trim curves A and B.
inline geom::NurbsSurface yang_surface() {
    const double a = 1.0 / 3.0, b = 0.2;
    const std::vector<Eigen::Vector3d> rows = {
        {-1, -1, -1}, {-a, -1, -b}, {a, -1, -b}, {1, -1, -1},
        {-1, -a, -b}, {-a, -a, 1},  {a, -a, 1},  {1, -a, -b},
        {-1, a, -b},  {-a, a, 1},   {a, a, 1},   {1, a, -b},
        {-1, 1, -1},  {-a, 1, -b},  {a, 1, -b},  {1, 1, -1}};
    std::vector<Eigen::Vector3d> P(16);
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) P[i * 4 + j] = rows[4 * j + i];  // point(i, j): i along u
    const std::vector<double> U = {0, 0, 0, 0, 1, 1, 1, 1};
    return geom::NurbsSurface(3, 3, U, U, 4, 4, P);
}
inline geom::NurbsCurve2d yang_curve(bool curve_b) {
    const std::vector<double> U = {0, 0, 0, 0, 1, 1, 1, 1};
    if (curve_b) return geom::NurbsCurve2d(3, U, {{.35, 0}, {.95, .06}, {.75, .9}, {.32, 1}});
    return geom::NurbsCurve2d(3, U, {{.35, 0}, {.8, .3}, {.75, .9}, {.3, 1}});
}

inline double point_segment_distance(const Eigen::Vector3d& x, const Eigen::Vector3d& a,
                                     const Eigen::Vector3d& b) {
    const Eigen::Vector3d ab = b - a;
    const double l2 = ab.squaredNorm();
    const double s = l2 > 0 ? std::clamp((x - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
    return (x - a - s * ab).norm();
}

inline double point_polyline_distance(const Eigen::Vector3d& x,
                                      const std::vector<Eigen::Vector3d>& line) {
    double d = (x - line.front()).norm();
    for (size_t i = 0; i + 1 < line.size(); ++i)
        d = std::min(d, point_segment_distance(x, line[i], line[i + 1]));
    return d;
}

// Two-sided deviation between a trim polyline and the exact curve S(c(t)), per
// segment against the curve over the segment's t range (sampled densely): points
// on the 3D segment, points S(lerp(uv)) (where the surface grid may add vertices),
// and curve points against the 3D segment.
struct Deviation {
    double chord = 0.0;    // 3D segment <-> curve
    double lifted = 0.0;   // S(lerp(uv)) -> curve
    double uv = 0.0;       // uv segment -> c (2D, for the [Yang] counterexample figures)
    double max() const { return std::max(chord, lifted); }
};

inline Deviation polyline_deviation(const geom::NurbsSurface& S, const geom::NurbsCurve2d& c,
                                    const tess::TrimPolyline& poly, int samples = 100) {
    Deviation dev;
    const auto& P = poly.points;
    for (size_t i = 0; i + 1 < P.size(); ++i) {
        std::vector<Eigen::Vector3d> curve, curve2;
        for (int k = 0; k <= samples; ++k) {
            const double t = P[i].t + (P[i + 1].t - P[i].t) * k / samples;
            const Eigen::Vector2d uv = c.evaluate(t);
            curve.push_back(S.evaluate(uv.x(), uv.y()));
            curve2.push_back(Eigen::Vector3d(uv.x(), uv.y(), 0));
        }
        for (int k = 0; k <= samples; ++k) {
            const double a = double(k) / samples;
            const Eigen::Vector3d x = (1 - a) * P[i].xyz + a * P[i + 1].xyz;
            const Eigen::Vector2d uv = (1 - a) * P[i].uv + a * P[i + 1].uv;
            dev.chord = std::max(dev.chord, point_polyline_distance(x, curve));
            dev.chord = std::max(dev.chord, point_segment_distance(curve[k], P[i].xyz, P[i + 1].xyz));
            dev.lifted = std::max(dev.lifted,
                                  point_polyline_distance(S.evaluate(uv.x(), uv.y()), curve));
            dev.uv = std::max(dev.uv, point_polyline_distance(Eigen::Vector3d(uv.x(), uv.y(), 0), curve2));
        }
    }
    return dev;
}

}  // namespace trimkit::test
