// Small meshes shared by the mesh and writer tests: a unit square of two
// triangles and a cube made of six separately meshed quads (24 vertices, each
// face with its own normals, uvs and face id), both scalable.
#pragma once

#include <array>

#include "mesh/mesh.h"

namespace trimkit::test {

// The square [0, s]^2 in z = 0, normal +z, uv = position / s, face id 0.
inline mesh::Mesh square_mesh(double s = 1.0) {
    mesh::Mesh m;
    m.positions = {{0, 0, 0}, {s, 0, 0}, {s, s, 0}, {0, s, 0}};
    m.normals.assign(4, Eigen::Vector3d::UnitZ());
    m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    m.face_ids = {0, 0};
    return m;
}

// The cube [0, s]^3 with outward normals; face f (0..5) has vertices 4f..4f+3,
// triangles 2f, 2f+1, face id f and boundary edges flagged kFaceBoundary.
inline mesh::Mesh cube_mesh(double s = 1.0, const Eigen::Vector3d& origin = Eigen::Vector3d::Zero()) {
    mesh::Mesh m;
    // Each face: outward normal n, in-plane axes a, b with a x b = n.
    const std::array<std::array<Eigen::Vector3d, 3>, 6> frames = {{
        {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1)},
        {Eigen::Vector3d(-1, 0, 0), Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(0, 1, 0)},
        {Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 0)},
        {Eigen::Vector3d(0, -1, 0), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 0, 1)},
        {Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0)},
        {Eigen::Vector3d(0, 0, -1), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(1, 0, 0)},
    }};
    const Eigen::Vector3d centre = origin + Eigen::Vector3d::Constant(0.5 * s);
    for (int f = 0; f < 6; ++f) {
        const auto& [n, a, b] = frames[f];
        const int base = 4 * f;
        const std::array<Eigen::Vector2d, 4> corners = {
            Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0), Eigen::Vector2d(1, 1), Eigen::Vector2d(0, 1)};
        for (const auto& c : corners) {
            m.positions.push_back(centre + 0.5 * s * (n + (2 * c.x() - 1) * a + (2 * c.y() - 1) * b));
            m.normals.push_back(n);
            m.uvs.push_back(c);
        }
        m.triangles.push_back({base, base + 1, base + 2});
        m.triangles.push_back({base, base + 2, base + 3});
        m.face_ids.push_back(f);
        m.face_ids.push_back(f);
        for (int k = 0; k < 4; ++k)
            m.edges.push_back({base + k, base + (k + 1) % 4, mesh::kFaceBoundary});
    }
    m.face_colors = {{{1, 0, 0}}, {{0, 1, 0}}, {{0, 0, 1}}, {{1, 1, 0}}, {{0, 1, 1}}, {{1, 0, 1}}};
    return m;
}

}  // namespace trimkit::test
