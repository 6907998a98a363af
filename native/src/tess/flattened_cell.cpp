#include "tess/flattened_cell.h"

#include <unordered_map>

#include "mesh/triangulate_polygon.h"

namespace trimkit::tess {
namespace {

Eigen::Vector3d triangle_normal(const std::vector<Eigen::Vector3d>& xyz, const std::array<int, 3>& t) {
    return (xyz[t[1]] - xyz[t[0]]).cross(xyz[t[2]] - xyz[t[0]]);
}

bool backward(const geom::NurbsSurface& s, const std::vector<Eigen::Vector2d>& uv,
              const std::vector<Eigen::Vector3d>& xyz, const std::array<int, 3>& t) {
    const Eigen::Vector3d n = triangle_normal(xyz, t);
    if (!(n.norm() > 0.0)) return false;
    const Eigen::Vector2d c = (uv[t[0]] + uv[t[1]] + uv[t[2]]) / 3.0;
    return n.normalized().dot(s.normal(c.x(), c.y())) < 0.0;
}

}  // namespace

bool has_backward_triangle(const geom::NurbsSurface& s, const std::vector<Eigen::Vector2d>& uv,
                           const std::vector<Eigen::Vector3d>& xyz,
                           const std::vector<std::array<int, 3>>& triangles) {
    for (const auto& t : triangles)
        if (backward(s, uv, xyz, t)) return true;
    return false;
}

std::vector<std::array<int, 3>> triangulate_in_3d_plane(const geom::NurbsSurface& s,
                                                        const std::vector<Eigen::Vector2d>& uv,
                                                        const std::vector<Eigen::Vector3d>& xyz,
                                                        const std::vector<int>& outer,
                                                        const std::vector<std::vector<int>>& holes,
                                                        mesh::Deadline* deadline) {
    // Local numbering of the polygon's vertices, projected onto the plane (e1, e2)
    // with e1 x e2 = n, so counter-clockwise in (u,v) stays counter-clockwise.
    Eigen::AlignedBox2d box;
    for (int i : outer) box.extend(uv[i]);
    const Eigen::Vector3d n = s.normal(box.center().x(), box.center().y());
    const Eigen::Vector3d e1 = n.unitOrthogonal(), e2 = n.cross(e1);
    std::unordered_map<int, int> local;
    std::vector<int> global;
    std::vector<Eigen::Vector2d> plane;
    auto number = [&](const std::vector<int>& ring) {
        std::vector<int> out;
        for (int i : ring) {
            auto [it, fresh] = local.emplace(i, static_cast<int>(global.size()));
            if (fresh) {
                global.push_back(i);
                plane.emplace_back(xyz[i].dot(e1), xyz[i].dot(e2));
            }
            out.push_back(it->second);
        }
        return out;
    };
    const std::vector<int> ring = number(outer);
    std::vector<std::vector<int>> local_holes;
    for (const auto& h : holes) local_holes.push_back(number(h));
    std::vector<std::array<int, 3>> out = mesh::triangulate_polygon(plane, ring, local_holes, deadline);
    for (auto& t : out)
        for (int& v : t) v = global[v];
    if (has_backward_triangle(s, uv, xyz, out)) return {};
    return out;
}

}  // namespace trimkit::tess
