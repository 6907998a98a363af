// The arrangement of cut segments inside one triangle of a patch's domain
// ([Garcia] Sec. 5 phases b and c): the segments and the triangle's sides are
// split at every crossing, dangling ends are dropped, and the triangle is cut
// into faces (simple polygons), each triangulated by mesh/triangulate_polygon.h.
// Coordinates are the triangle's local barycentric (alpha, beta) with corners (1,0),
// (0,1), (0,0) (roles u, v, w of the node), so the same tolerance fits every level.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

namespace trimkit::tbp {

// Points closer than this (local coordinates, the triangle's legs have length
// 1) are one point: segment ends computed in neighbouring leaves or by
// neighbouring tool patches differ by rounding (~1e-15).
constexpr double kArrangementSnap = 1e-10;

struct ArrangementFace {
    std::vector<int> polygon;                     // counter-clockwise, indices into points
    std::vector<std::array<int, 3>> triangles;    // its triangulation, counter-clockwise
    Eigen::Vector2d sample = Eigen::Vector2d::Zero();  // a point well inside (centroid of its largest triangle)
};

struct TriangleArrangement {
    std::vector<Eigen::Vector2d> points;  // corners first (0: (1,0), 1: (0,1), 2: (0,0))
    std::vector<ArrangementFace> faces;   // cover the triangle
};

// Faces of the unit triangle cut by `cuts` (segments in local coordinates;
// ends slightly outside the triangle are clamped onto it). Closed cuts that
// touch nothing are joined to the sides by two auxiliary cuts so every face
// is simply connected.
TriangleArrangement arrange_triangle(const std::vector<std::array<Eigen::Vector2d, 2>>& cuts);

// Local (alpha, beta) of the point with barycentric coordinates `l` (sum 1).
inline Eigen::Vector2d local_point(const Eigen::Vector3d& l) { return {l[0], l[1]}; }
inline Eigen::Vector3d local_barycentric(const Eigen::Vector2d& p) { return {p.x(), p.y(), 1 - p.x() - p.y()}; }

}  // namespace trimkit::tbp
