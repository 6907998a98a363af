// TriangleBvh: an axis-aligned bounding-box tree over triangles for closest-point
// queries (the nearest triangle to a point, and every triangle within a radius).
// Triangles are given as three corner indices into a shared array of 3D points;
// results name the triangle by its index in that list and give the closest point with
// its barycentric coordinates (weights of corners 0, 1, 2, summing to 1).
// Standalone on purpose (no OCCT, no trimkit): used by occt_check on both meshes.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace occt_reference {

struct Vec3 {
  double x = 0, y = 0, z = 0;
};
inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator-(Vec3 a, Vec3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 operator*(double s, Vec3 a) { return {s * a.x, s * a.y, s * a.z}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Vec3 cross(Vec3 a, Vec3 b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(Vec3 a) { return std::sqrt(dot(a, a)); }

// Closest point to p on triangle (a, b, c), with barycentric weights of a, b, c.
// Ericson, Real-Time Collision Detection, Sec. 5.1.5 (Voronoi regions of the corners and
// sides); works for degenerate (zero-area) triangles too.
struct TrianglePoint {
  Vec3 point;
  std::array<double, 3> weights;
};
inline TrianglePoint closest_on_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return {a, {1, 0, 0}};
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return {b, {0, 1, 0}};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const double v = d1 / (d1 - d3);
    return {a + v * ab, {1 - v, v, 0}};
  }
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return {c, {0, 0, 1}};
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const double w = d2 / (d2 - d6);
    return {a + w * ac, {1 - w, 0, w}};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {b + w * (c - b), {0, 1 - w, w}};
  }
  const double sum = va + vb + vc;
  if (!(sum > 0)) {  // degenerate triangle that passed the region tests: nearest corner
    const double da = dot(ap, ap), db = dot(bp, bp), dc = dot(cp, cp);
    if (da <= db && da <= dc) return {a, {1, 0, 0}};
    return db <= dc ? TrianglePoint{b, {0, 1, 0}} : TrianglePoint{c, {0, 0, 1}};
  }
  const double v = vb / sum, w = vc / sum;
  return {a + v * ab + w * ac, {1 - v - w, v, w}};
}

class TriangleBvh {
 public:
  struct Hit {
    int triangle = -1;
    double distance = std::numeric_limits<double>::infinity();
    TrianglePoint on;
  };

  // points: corner positions; triangles: corner indices (kept by reference: both must
  // outlive the tree).
  TriangleBvh(const std::vector<Vec3>& points, const std::vector<std::array<int, 3>>& triangles)
      : points_(points), triangles_(triangles) {
    const int n = static_cast<int>(triangles.size());
    order_.resize(n);
    std::vector<Vec3> centre(n);
    for (int t = 0; t < n; ++t) {
      order_[t] = t;
      const auto& tri = triangles[t];
      centre[t] = (1.0 / 3.0) * (points[tri[0]] + points[tri[1]] + points[tri[2]]);
    }
    if (n == 0) return;
    nodes_.reserve(2 * (n / kLeafSize + 1));
    nodes_.resize(1);
    build(0, 0, n, centre);
  }

  // The triangle nearest to p (triangle -1 for an empty tree).
  Hit nearest(Vec3 p) const {
    Hit best;
    if (nodes_.empty()) return best;
    double best2 = std::numeric_limits<double>::infinity();
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[stack[--top]];
      if (box_distance2(node, p) >= best2) continue;
      if (node.count > 0) {
        for (int k = node.first; k < node.first + node.count; ++k) {
          const auto& tri = triangles_[order_[k]];
          const TrianglePoint on = closest_on_triangle(p, points_[tri[0]], points_[tri[1]], points_[tri[2]]);
          const Vec3 d = p - on.point;
          const double d2 = dot(d, d);
          if (d2 < best2) {
            best2 = d2;
            best.triangle = order_[k];
            best.on = on;
          }
        }
        continue;
      }
      // Visit the nearer child first (pushed last).
      const int a = node.first, b = node.first + 1;
      const double da = box_distance2(nodes_[a], p), db = box_distance2(nodes_[b], p);
      if (da <= db) {
        if (db < best2) stack[top++] = b;
        if (da < best2) stack[top++] = a;
      } else {
        if (da < best2) stack[top++] = a;
        if (db < best2) stack[top++] = b;
      }
    }
    best.distance = std::sqrt(best2);
    return best;
  }

  // Calls visit(Hit) for every triangle whose closest point is within `radius` of p.
  template <class Visit>
  void within(Vec3 p, double radius, Visit&& visit) const {
    if (nodes_.empty()) return;
    const double r2 = radius * radius;
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& node = nodes_[stack[--top]];
      if (box_distance2(node, p) > r2) continue;
      if (node.count > 0) {
        for (int k = node.first; k < node.first + node.count; ++k) {
          const auto& tri = triangles_[order_[k]];
          const TrianglePoint on = closest_on_triangle(p, points_[tri[0]], points_[tri[1]], points_[tri[2]]);
          const Vec3 d = p - on.point;
          const double d2 = dot(d, d);
          if (d2 <= r2) visit(Hit{order_[k], std::sqrt(d2), on});
        }
        continue;
      }
      stack[top++] = node.first;
      stack[top++] = node.first + 1;
    }
  }

 private:
  // Leaf: count > 0 triangles order_[first, first + count). Inner: count == 0, children
  // at nodes_[first] and nodes_[first + 1].
  struct Node {
    Vec3 lo, hi;
    int first = 0, count = 0;
  };
  static constexpr int kLeafSize = 4;

  static double box_distance2(const Node& node, Vec3 p) {
    const double dx = std::max({node.lo.x - p.x, 0.0, p.x - node.hi.x});
    const double dy = std::max({node.lo.y - p.y, 0.0, p.y - node.hi.y});
    const double dz = std::max({node.lo.z - p.z, 0.0, p.z - node.hi.z});
    return dx * dx + dy * dy + dz * dz;
  }

  // Fills nodes_[slot] with the subtree over order_[begin, end): a leaf when small,
  // else a median split on the longest axis of the centres' box, the two children
  // allocated as a pair. Depth stays below log2(n) + 2 < 128 (the query stacks).
  void build(int slot, int begin, int end, const std::vector<Vec3>& centre) {
    Node node;
    const double inf = std::numeric_limits<double>::infinity();
    node.lo = {inf, inf, inf};
    node.hi = {-inf, -inf, -inf};
    Vec3 clo = node.lo, chi = node.hi;
    for (int k = begin; k < end; ++k) {
      for (const int v : triangles_[order_[k]]) grow(node.lo, node.hi, points_[v]);
      grow(clo, chi, centre[order_[k]]);
    }
    if (end - begin <= kLeafSize) {
      node.first = begin;
      node.count = end - begin;
      nodes_[slot] = node;
      return;
    }
    const Vec3 extent = chi - clo;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const auto coordinate = [axis](Vec3 v) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; };
    const int middle = begin + (end - begin) / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + middle, order_.begin() + end,
                     [&](int a, int b) { return coordinate(centre[a]) < coordinate(centre[b]); });
    node.first = static_cast<int>(nodes_.size());
    node.count = 0;
    nodes_[slot] = node;
    nodes_.resize(nodes_.size() + 2);
    build(node.first, begin, middle, centre);
    build(node.first + 1, middle, end, centre);
  }

  static void grow(Vec3& lo, Vec3& hi, Vec3 p) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }

  const std::vector<Vec3>& points_;
  const std::vector<std::array<int, 3>>& triangles_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
};

}  // namespace occt_reference
