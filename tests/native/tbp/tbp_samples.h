// Sample TBP solids and patches for the tbp tests: flat patches of any degree,
// the unit cube [0,1]^3 as 12 flat patches with outward normals, a flat square.
#pragma once

#include <array>
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
