// Models built in the fit tests ([Muraki]'s cases): a planar face with holes, a
// concave (L-shaped) face on a curved surface, and a strip of three faces on one
// smooth surface, the middle one between two G1 neighbours, with a hole across
// one shared edge (Fig. 5 and 10). Edges are 3D curves fitted by add_coedge_edges.
#pragma once

#include <cmath>
#include <stdexcept>

#include "fit/coedge_edges.h"
#include "geom/analytic_curves.h"
#include "geom/analytic_surfaces.h"
#include "geom/knot_vector.h"
#include "geom/model.h"

namespace trimkit::fit::test {

constexpr double kEdgeFit = 1e-5;

inline geom::Loop polygon_loop(const std::vector<Eigen::Vector2d>& corners, bool outer) {
    geom::Loop loop;
    loop.outer = outer;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        geom::Coedge c;
        c.curve = geom::line_segment(corners[i], corners[(i + 1) % corners.size()]);
        loop.coedges.push_back(c);
    }
    return loop;
}

// A clockwise circle (a hole) of radius r about c in (u, v): two half arcs.
inline geom::Loop circle_hole(const Eigen::Vector2d& c, double r) {
    geom::Loop loop;
    for (int half = 0; half < 2; ++half) {
        geom::Coedge e;
        e.curve = geom::to_2d(geom::circular_arc({c.x(), c.y(), 0}, {1, 0, 0}, {0, -1, 0}, r, half * M_PI, (half + 1) * M_PI));
        loop.coedges.push_back(e);
    }
    return loop;
}

inline void add_face(geom::Model& m, geom::Face f) {
    m.faces.push_back(std::move(f));
    m.free_faces.push_back(static_cast<int>(m.faces.size()) - 1);
    if (!fit::add_coedge_edges(m, static_cast<int>(m.faces.size()) - 1, kEdgeFit))
        throw std::runtime_error("fit_models: an edge curve does not fit within kEdgeFit");
}

// 10 x 6 plate in the plane z = x/10 + 2 with two round holes.
inline geom::Model plate_with_holes() {
    geom::Face f;
    f.surface = geom::plane_patch({0, 0, 2}, {1, 0, 0.1}, {0, 1, 0}, 0, 10, 0, 6);
    f.loops = {polygon_loop({{0, 0}, {10, 0}, {10, 6}, {0, 6}}, true), circle_hole({3, 3}, 1.2), circle_hole({7, 2.5}, 1)};
    geom::Model m;
    add_face(m, f);
    return m;
}

// A gently curved bicubic over [0, 4]² (z up to ~0.4 of the 4-unit size).
inline geom::NurbsSurface curved_surface(int nu = 5, double width = 4.0) {
    std::vector<Eigen::Vector3d> P;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < 5; ++j) {
            const double x = width * i / (nu - 1), y = 4.0 * j / 4;
            P.push_back({x, y, 0.1 * (x - width / 2) * (x - width / 2) * 0.25 + 0.05 * y * y});
        }
    return geom::NurbsSurface(3, 3, geom::uniform_clamped_knots(nu, 3, 0, width), geom::uniform_clamped_knots(5, 3, 0, 4),
                              nu, 5, P);
}

// An L-shaped (concave) face on the curved surface.
inline geom::Model concave_face() {
    geom::Face f;
    f.surface = curved_surface();
    f.loops = {polygon_loop({{0.2, 0.2}, {3.8, 0.2}, {3.8, 1.6}, {1.6, 1.6}, {1.6, 3.8}, {0.2, 3.8}}, true)};
    geom::Model m;
    add_face(m, f);
    return m;
}

// Three faces on one surface over [0, 6] x [0, 4]: u in [0, 2], [2, 4], [4, 6].
// The middle face (index 1) has a hole across its shared edge u = 4 with face 2:
// the hole cuts both faces, so the shared edge is two edges, below and above it.
inline geom::Model g1_strip() {
    const geom::NurbsSurface S = curved_surface(7, 6.0);
    geom::Model m;
    geom::Face a;
    a.surface = S;
    a.loops = {polygon_loop({{0, 0}, {2, 0}, {2, 4}, {0, 4}}, true)};
    add_face(m, a);
    // Middle face: (2,0) (4,0) (4,1.5) arc to (4,2.5) (4,4) (2,4); the notch is a
    // half circle of radius 0.5 about (4, 2) bulging into the face.
    geom::Face b;
    b.surface = S;
    geom::Loop outer = polygon_loop({{2, 0}, {4, 0}, {4, 1.5}}, true);
    outer.coedges.pop_back();  // (4,1.5) -> (2,0) is not an edge
    geom::Coedge notch;
    notch.curve = geom::to_2d(geom::circular_arc({4, 2, 0}, {0, -1, 0}, {-1, 0, 0}, 0.5, 0, M_PI));
    outer.coedges.push_back(notch);
    for (const auto& [p, q] : {std::pair<Eigen::Vector2d, Eigen::Vector2d>{{4, 2.5}, {4, 4}}, {{4, 4}, {2, 4}}, {{2, 4}, {2, 0}}}) {
        geom::Coedge c;
        c.curve = geom::line_segment(p, q);
        outer.coedges.push_back(c);
    }
    b.loops = {outer};
    // Its left coedge (2,4) -> (2,0) is face a's right edge (2,0) -> (2,4), reversed.
    b.loops[0].coedges[5].edge = a.loops.empty() ? -1 : m.faces[0].loops[0].coedges[1].edge;
    b.loops[0].coedges[5].edge_reversed = true;
    add_face(m, b);
    geom::Face c;
    c.surface = S;
    geom::Loop right = polygon_loop({{4, 0}, {6, 0}, {6, 4}, {4, 4}, {4, 2.5}}, true);
    right.coedges.pop_back();  // (4,2.5) -> (4,0) is replaced by the notch's other side
    geom::Coedge other_notch;
    other_notch.curve = geom::to_2d(geom::circular_arc({4, 2, 0}, {0, 1, 0}, {1, 0, 0}, 0.5, 0, M_PI));
    right.coedges.push_back(other_notch);
    geom::Coedge down;
    down.curve = geom::line_segment(Eigen::Vector2d(4, 1.5), Eigen::Vector2d(4, 0));
    right.coedges.push_back(down);
    c.loops = {right};
    // Shared with the middle face: (4,4) -> (4,2.5) is b's (4,2.5) -> (4,4) and (4,1.5) -> (4,0) is b's (4,0) -> (4,1.5).
    c.loops[0].coedges[3].edge = m.faces[1].loops[0].coedges[3].edge;
    c.loops[0].coedges[3].edge_reversed = true;
    c.loops[0].coedges[5].edge = m.faces[1].loops[0].coedges[1].edge;
    c.loops[0].coedges[5].edge_reversed = true;
    add_face(m, c);
    return m;
}

}  // namespace trimkit::fit::test
