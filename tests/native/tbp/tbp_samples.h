// Sample TBP solids and patches for the tbp tests: flat patches of any degree,
// the unit cube [0,1]^3 as 12 flat patches with outward normals, a flat square.
#pragma once

#include <array>
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "tbp/tbp_solid.h"

namespace trimkit::tbp::test {

// The flat degree-n patch over the triangle (a, b, c): b_ijk = (i a + j b + k c) / n.
inline TbpPatch flat_patch(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, int n = 3) {
    std::vector<Eigen::Vector3d> P;
    for (int i = n; i >= 0; --i)
        for (int j = n - i; j >= 0; --j) P.push_back((i * a + j * b + (n - i - j) * c) / n);
    return TbpPatch(n, P);
}

// Two flat patches over the quad p0 p1 p2 p3 (counter-clockwise seen from the normal side).
inline void add_quad(std::vector<TbpPatch>& out, const Eigen::Vector3d& p0, const Eigen::Vector3d& p1,
                     const Eigen::Vector3d& p2, const Eigen::Vector3d& p3, int n = 3) {
    out.push_back(flat_patch(p0, p1, p2, n));
    out.push_back(flat_patch(p0, p2, p3, n));
}

// The box [lo, hi] as 12 flat patches, normals pointing out.
inline TbpSolid box_solid(const Eigen::Vector3d& lo = Eigen::Vector3d::Zero(),
                          const Eigen::Vector3d& hi = Eigen::Vector3d::Ones(), int n = 3) {
    auto v = [&](int x, int y, int z) {
        return Eigen::Vector3d(x ? hi.x() : lo.x(), y ? hi.y() : lo.y(), z ? hi.z() : lo.z());
    };
    TbpSolid s;
    s.name = "box";
    add_quad(s.patches, v(0, 0, 0), v(0, 1, 0), v(1, 1, 0), v(1, 0, 0), n);  // z = lo, normal -z
    add_quad(s.patches, v(0, 0, 1), v(1, 0, 1), v(1, 1, 1), v(0, 1, 1), n);  // z = hi, +z
    add_quad(s.patches, v(0, 0, 0), v(1, 0, 0), v(1, 0, 1), v(0, 0, 1), n);  // y = lo, -y
    add_quad(s.patches, v(0, 1, 0), v(0, 1, 1), v(1, 1, 1), v(1, 1, 0), n);  // y = hi, +y
    add_quad(s.patches, v(0, 0, 0), v(0, 0, 1), v(0, 1, 1), v(0, 1, 0), n);  // x = lo, -x
    add_quad(s.patches, v(1, 0, 0), v(1, 1, 0), v(1, 1, 1), v(1, 0, 1), n);  // x = hi, +x
    return s;
}

}  // namespace trimkit::tbp::test

#include <map>

#include "mesh/mesh.h"

namespace trimkit::tbp::test {

// An icosphere of radius r around c: the icosahedron subdivided `levels` times,
// vertices pushed onto the sphere; triangles counter-clockwise seen from outside.
inline mesh::Mesh icosphere(int levels, double r = 1.0, const Eigen::Vector3d& c = Eigen::Vector3d::Zero()) {
    const double t = (1 + std::sqrt(5.0)) / 2;
    std::vector<Eigen::Vector3d> V = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                      {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (auto& v : V) v.normalize();
    std::vector<std::array<int, 3>> F = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                         {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                         {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                         {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int l = 0; l < levels; ++l) {
        std::map<std::pair<int, int>, int> mid;
        auto m = [&](int a, int b) {
            auto key = std::minmax(a, b);
            auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            V.push_back((V[a] + V[b]).normalized());
            return mid[key] = static_cast<int>(V.size()) - 1;
        };
        std::vector<std::array<int, 3>> G;
        for (const auto& f : F) {
            const int a = m(f[0], f[1]), b = m(f[1], f[2]), cc = m(f[2], f[0]);
            G.push_back({f[0], a, cc}), G.push_back({f[1], b, a}), G.push_back({f[2], cc, b}), G.push_back({a, b, cc});
        }
        F = G;
    }
    mesh::Mesh out;
    for (const auto& v : V) out.positions.push_back(c + r * v);
    for (const auto& f : F) out.triangles.push_back({f[0], f[1], f[2]});
    return out;
}

}  // namespace trimkit::tbp::test
