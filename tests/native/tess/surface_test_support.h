// Shared cases for the surface-side tessellation tests: a bicubic patch, trim
// polygons sampled from S, and the deviation measure between a mesh and S.
#pragma once

#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "geom/analytic_curves.h"
#include "geom/analytic_surfaces.h"
#include "geom/face.h"
#include "geom/nurbs_surface.h"
#include "mesh/mesh.h"
#include "tess/trim_polyline.h"

namespace trimkit::tess::test {

// A bicubic Bezier patch over [0,1]^2 with a bump: x, y in [0, scale], z up to ~0.4 scale.
inline geom::NurbsSurface bicubic_patch(double scale = 1.0, bool rational = false) {
    std::vector<Eigen::Vector3d> P;
    std::vector<double> w;
    const double z[4][4] = {{0, 0.2, 0.1, 0}, {0.1, 0.6, 0.5, 0.1}, {0, 0.5, 0.7, 0.2}, {0, 0.1, 0.2, 0}};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            P.emplace_back(scale * i / 3.0, scale * j / 3.0, scale * z[i][j]);
            w.push_back(rational ? 1.0 + 0.5 * ((i + j) % 2) : 1.0);
        }
    return geom::NurbsSurface(3, 3, {0, 0, 0, 0, 1, 1, 1, 1}, {0, 0, 0, 0, 1, 1, 1, 1}, 4, 4, P,
                              rational ? w : std::vector<double>{});
}

// A bilinear patch (degree 1 x 1) with a twist.
inline geom::NurbsSurface bilinear_patch() {
    return geom::NurbsSurface(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2,
                              {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0.5}});
}

// x = u, y = v, z = u^2 + v^2 on [0,1]^2 as a biquadratic Bezier patch (z's control
// values a_i + a_j, a = (0, 0, 1)), or the plane z = 0 when `flat`, with the knots
// k / spans inserted `multiplicity` times each way: C^1 across them once, C^0 twice.
// S_uu = S_vv = (0, 0, 2), S_uv = 0.
inline geom::NurbsSurface paraboloid(int spans = 1, bool flat = false, int multiplicity = 1) {
    std::vector<Eigen::Vector3d> P;
    const double a[3] = {0, 0, 1};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) P.emplace_back(0.5 * i, 0.5 * j, flat ? 0.0 : a[i] + a[j]);
    geom::NurbsSurface S(2, 2, {0, 0, 0, 1, 1, 1}, {0, 0, 0, 1, 1, 1}, 3, 3, P);
    for (int k = 1; k < spans; ++k)
        for (int m = 0; m < multiplicity; ++m) S = S.insert_knot_u(double(k) / spans).insert_knot_v(double(k) / spans);
    return S;
}

// The ribbon between arcs of radius R and R + w about the origin over [0, sweep], on
// the plane z = 0 ((u,v) = (x,y) over [-60, 60]^2), as one outer loop of free coedges:
// the outer arc, the end line at `sweep`, the inner arc back, the end line at 0.
inline geom::Face ribbon_face(double R, double w, double sweep) {
    geom::Face face;
    face.surface = geom::plane_patch(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), -60,
                                     60, -60, 60);
    face.surface_kind = "plane";
    const auto arc = [&](double r) {
        return geom::to_2d(geom::circular_arc(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(),
                                              Eigen::Vector3d::UnitY(), r, 0.0, sweep));
    };
    const Eigen::Vector2d d(std::cos(sweep), std::sin(sweep));
    geom::Loop loop;
    loop.outer = true;
    loop.coedges = {{arc(R + w), -1, false},
                    {geom::line_segment(Eigen::Vector2d((R + w) * d), Eigen::Vector2d(R * d)), -1, false},
                    {arc(R).reversed(), -1, false},
                    {geom::line_segment(Eigen::Vector2d(R, 0), Eigen::Vector2d(R + w, 0)), -1, false}};
    face.loops.push_back(loop);
    return face;
}

inline PolylinePoint on_surface(const geom::NurbsSurface& S, double u, double v) {
    PolylinePoint p;
    p.uv = {u, v};
    p.xyz = S.evaluate(u, v);
    return p;
}

// Counter-clockwise rectangle [u0,u1] x [v0,v1] with n points per side.
inline TrimPolygon rectangle_loop(const geom::NurbsSurface& S, double u0, double u1, double v0,
                                  double v1, int n) {
    TrimPolygon loop;
    loop.outer = true;
    for (int k = 0; k < n; ++k) loop.points.push_back(on_surface(S, u0 + (u1 - u0) * k / n, v0));
    for (int k = 0; k < n; ++k) loop.points.push_back(on_surface(S, u1, v0 + (v1 - v0) * k / n));
    for (int k = 0; k < n; ++k) loop.points.push_back(on_surface(S, u1 - (u1 - u0) * k / n, v1));
    for (int k = 0; k < n; ++k) loop.points.push_back(on_surface(S, u0, v1 - (v1 - v0) * k / n));
    return loop;
}

// Circle of radius r around (cu, cv) in (u,v), n points; clockwise (a hole) unless outer.
inline TrimPolygon circle_loop(const geom::NurbsSurface& S, double cu, double cv, double r, int n,
                               bool outer = false) {
    TrimPolygon loop;
    loop.outer = outer;
    for (int k = 0; k < n; ++k) {
        const double a = (outer ? 2.0 : -2.0) * M_PI * k / n;
        loop.points.push_back(on_surface(S, cu + r * std::cos(a), cv + r * std::sin(a)));
    }
    return loop;
}

inline geom::Face face_of(const geom::NurbsSurface& S, bool reversed = false) {
    geom::Face face;
    face.surface = S;
    face.loops = {geom::natural_boundary_loop(S)};
    face.reversed = reversed;
    return face;
}

// Largest |sum l_i x_i - S(sum l_i uv_i)| over a barycentric grid of `steps` on
// every triangle: the parametric deviation of the mesh from S.
inline double parametric_deviation(const mesh::Mesh& mesh, const geom::NurbsSurface& S,
                                   int steps = 6) {
    double worst = 0.0;
    for (const auto& t : mesh.triangles)
        for (int a = 0; a <= steps; ++a)
            for (int b = 0; a + b <= steps; ++b) {
                const double l0 = double(a) / steps, l1 = double(b) / steps, l2 = 1.0 - l0 - l1;
                const Eigen::Vector3d x = l0 * mesh.positions[t[0]] + l1 * mesh.positions[t[1]] +
                                          l2 * mesh.positions[t[2]];
                const Eigen::Vector2d uv = l0 * mesh.uvs[t[0]] + l1 * mesh.uvs[t[1]] + l2 * mesh.uvs[t[2]];
                worst = std::max(worst, (x - S.evaluate(uv.x(), uv.y())).norm());
            }
    return worst;
}

// Distance from x to S by Newton projection from (u,v) (clamped to the domain).
inline double distance_to_surface(const geom::NurbsSurface& S, const Eigen::Vector3d& x,
                                  Eigen::Vector2d uv) {
    const auto [u0, u1] = S.domain_u();
    const auto [v0, v1] = S.domain_v();
    for (int it = 0; it < 20; ++it) {
        const auto d = S.derivatives(uv.x(), uv.y());
        const Eigen::Vector3d r = d.S - x;
        Eigen::Matrix2d J;
        J << d.Su.dot(d.Su) + r.dot(d.Suu), d.Su.dot(d.Sv) + r.dot(d.Suv),
            d.Su.dot(d.Sv) + r.dot(d.Suv), d.Sv.dot(d.Sv) + r.dot(d.Svv);
        const Eigen::Vector2d g(r.dot(d.Su), r.dot(d.Sv));
        Eigen::Vector2d step = J.ldlt().solve(-g);
        if (!step.allFinite()) break;
        uv += step;
        uv.x() = std::clamp(uv.x(), u0, u1);
        uv.y() = std::clamp(uv.y(), v0, v1);
        if (step.norm() < 1e-14) break;
    }
    return (S.evaluate(uv.x(), uv.y()) - x).norm();
}

// Largest distance from the barycentric samples of the mesh to S (by projection).
inline double surface_distance(const mesh::Mesh& mesh, const geom::NurbsSurface& S, int steps = 4) {
    double worst = 0.0;
    for (const auto& t : mesh.triangles)
        for (int a = 0; a <= steps; ++a)
            for (int b = 0; a + b <= steps; ++b) {
                const double l0 = double(a) / steps, l1 = double(b) / steps, l2 = 1.0 - l0 - l1;
                const Eigen::Vector3d x = l0 * mesh.positions[t[0]] + l1 * mesh.positions[t[1]] +
                                          l2 * mesh.positions[t[2]];
                const Eigen::Vector2d uv = l0 * mesh.uvs[t[0]] + l1 * mesh.uvs[t[1]] + l2 * mesh.uvs[t[2]];
                worst = std::max(worst, distance_to_surface(S, x, uv));
            }
    return worst;
}

// Area of S over the (u,v) region {inside outer, outside holes} by the midpoint rule
// on an n x n grid of [0,1]^2 (polygon membership by even-odd).
inline double trimmed_area(const geom::NurbsSurface& S, const std::vector<TrimPolygon>& loops, int n) {
    auto in_region = [&](const Eigen::Vector2d& p) {
        bool in = false;
        for (const auto& loop : loops) {
            const auto& q = loop.points;
            for (size_t i = 0, m = q.size(), j = m - 1; i < m; j = i++)
                if ((q[i].uv.y() > p.y()) != (q[j].uv.y() > p.y()) &&
                    p.x() < q[i].uv.x() + (p.y() - q[i].uv.y()) * (q[j].uv.x() - q[i].uv.x()) /
                                              (q[j].uv.y() - q[i].uv.y()))
                    in = !in;
        }
        return in;
    };
    double area = 0.0;
    const double h = 1.0 / n;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const Eigen::Vector2d p((i + 0.5) * h, (j + 0.5) * h);
            if (!in_region(p)) continue;
            const auto d = S.derivatives(p.x(), p.y());
            area += d.Su.cross(d.Sv).norm() * h * h;
        }
    return area;
}

}  // namespace trimkit::tess::test
