#include "tess/triangle_bvh.h"

#include <algorithm>
#include <cmath>

namespace trimkit::tess {

Eigen::Vector3d closest_point_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                          const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
    const Eigen::Vector3d ab = b - a, ac = c - a, ap = p - a;
    const double d1 = ab.dot(ap), d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const Eigen::Vector3d bp = p - b;
    const double d3 = ab.dot(bp), d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        const double den = d1 - d3;
        return den > 0 ? Eigen::Vector3d(a + (d1 / den) * ab) : a;
    }
    const Eigen::Vector3d cp = p - c;
    const double d5 = ab.dot(cp), d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        const double den = d2 - d6;
        return den > 0 ? Eigen::Vector3d(a + (d2 / den) * ac) : a;
    }
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
        const double den = (d4 - d3) + (d5 - d6);
        return den > 0 ? Eigen::Vector3d(b + ((d4 - d3) / den) * (c - b)) : b;
    }
    const double sum = va + vb + vc;
    if (!(sum > 0)) {
        // Degenerate (collinear) triangle: the closest of its three edges.
        Eigen::Vector3d best = a;
        double bd = (p - a).squaredNorm();
        const Eigen::Vector3d* v[3] = {&a, &b, &c};
        for (int k = 0; k < 3; ++k) {
            const Eigen::Vector3d& s = *v[k];
            const Eigen::Vector3d e = *v[(k + 1) % 3] - s;
            const double ee = e.squaredNorm();
            const double t = ee > 0 ? std::clamp(e.dot(p - s) / ee, 0.0, 1.0) : 0.0;
            const Eigen::Vector3d q = s + t * e;
            if ((p - q).squaredNorm() < bd) {
                bd = (p - q).squaredNorm();
                best = q;
            }
        }
        return best;
    }
    const double v = vb / sum, w = vc / sum;
    return a + ab * v + ac * w;
}

TriangleBvh::TriangleBvh(const mesh::Mesh& mesh) : mesh_(mesh) {
    const int n = static_cast<int>(mesh.triangles.size());
    order_.resize(n);
    std::vector<Eigen::Vector3d> centroids(n);
    for (int t = 0; t < n; ++t) {
        order_[t] = t;
        const auto& tri = mesh.triangles[t];
        centroids[t] = (mesh.positions[tri[0]] + mesh.positions[tri[1]] + mesh.positions[tri[2]]) / 3.0;
    }
    nodes_.reserve(2 * static_cast<std::size_t>(n / kBvhLeafSize + 1));
    if (n > 0) build(0, n, centroids);
}

int TriangleBvh::build(int first, int count, std::vector<Eigen::Vector3d>& centroids) {
    const int index = static_cast<int>(nodes_.size());
    nodes_.emplace_back();
    Eigen::AlignedBox3d box, cbox;
    for (int k = first; k < first + count; ++k) {
        const auto& tri = mesh_.triangles[order_[k]];
        for (int c = 0; c < 3; ++c) box.extend(mesh_.positions[tri[c]]);
        cbox.extend(centroids[order_[k]]);
    }
    nodes_[index].box = box;
    if (count <= kBvhLeafSize) {
        nodes_[index].first = first;
        nodes_[index].count = count;
        return index;
    }
    int axis = 0;
    cbox.diagonal().maxCoeff(&axis);
    const int half = count / 2;
    std::nth_element(order_.begin() + first, order_.begin() + first + half, order_.begin() + first + count,
                     [&](int a, int b) { return centroids[a][axis] < centroids[b][axis]; });
    const int left = build(first, half, centroids);
    const int right = build(first + half, count - half, centroids);
    nodes_[index].left = left;
    nodes_[index].right = right;
    return index;
}

TriangleBvh::Hit TriangleBvh::closest(const Eigen::Vector3d& x, double max_distance) const {
    Hit hit;
    if (nodes_.empty()) return hit;
    double best = max_distance * max_distance;
    int stack[128];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        if (node.box.squaredExteriorDistance(x) >= best) continue;
        if (node.count > 0) {
            for (int k = node.first; k < node.first + node.count; ++k) {
                const auto& tri = mesh_.triangles[order_[k]];
                const Eigen::Vector3d q = closest_point_on_triangle(
                    x, mesh_.positions[tri[0]], mesh_.positions[tri[1]], mesh_.positions[tri[2]]);
                const double d = (q - x).squaredNorm();
                if (d < best || (hit.triangle < 0 && d <= best)) {
                    best = d;
                    hit.triangle = order_[k];
                    hit.point = q;
                }
            }
            continue;
        }
        // Push the farther child first so the nearer one is searched first.
        const double dl = nodes_[node.left].box.squaredExteriorDistance(x);
        const double dr = nodes_[node.right].box.squaredExteriorDistance(x);
        if (dl < dr) {
            stack[top++] = node.right;
            stack[top++] = node.left;
        } else {
            stack[top++] = node.left;
            stack[top++] = node.right;
        }
    }
    if (hit.triangle >= 0) hit.distance = std::sqrt(best);
    return hit;
}

}  // namespace trimkit::tess
