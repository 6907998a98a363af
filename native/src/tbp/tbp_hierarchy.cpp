#include "tbp/tbp_hierarchy.h"

#include <string>

#include "geom/error.h"

namespace trimkit::tbp {

std::vector<std::array<Eigen::Vector3d, 3>> uniform_subtriangles(int m) {
    // Grid point (a, b) is (u, v, w) = (a/m, b/m, 1 - (a+b)/m).
    auto g = [m](int a, int b) { return Eigen::Vector3d(double(a) / m, double(b) / m, double(m - a - b) / m); };
    std::vector<std::array<Eigen::Vector3d, 3>> out;
    out.reserve(static_cast<std::size_t>(m) * m);
    for (int b = 0; b < m; ++b)
        for (int a = 0; a + b < m; ++a) {
            // up: the parent scaled by 1/m around grid point (a, b) (its w corner)
            out.push_back({g(a + 1, b), g(a, b + 1), g(a, b)});
            // down: the parent rotated by 180 degrees, w corner at (a+1, b+1)
            if (a + b + 2 <= m) out.push_back({g(a, b + 1), g(a + 1, b), g(a + 1, b + 1)});
        }
    return out;
}

TbpHierarchy::TbpHierarchy(TbpPatch patch, int levels, int lod) : levels_(levels), lod_(lod) {
    if (levels < 0 || lod < 0)
        throw geom::InvalidInput("TbpHierarchy: levels " + std::to_string(levels) + ", lod " + std::to_string(lod) +
                                 "; both must be >= 0");
    long long leaves = 1;
    for (int l = 0; l < levels; ++l) {
        leaves *= static_cast<long long>(lod + 1) * (lod + 1);
        if (leaves > kMaxHierarchyLeaves)
            throw geom::InvalidInput("TbpHierarchy: levels " + std::to_string(levels) + " and lod " +
                                     std::to_string(lod) + " give more than " + std::to_string(kMaxHierarchyLeaves) +
                                     " leaves");
    }
    const auto sub = uniform_subtriangles(split());
    TbpNode root;
    root.domain = {Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 1, 0), Eigen::Vector3d(0, 0, 1)};
    root.box = patch.bounding_box();
    root.patch = std::move(patch);
    levels_data_.push_back({std::move(root)});
    for (int l = 0; l < levels; ++l) {
        const std::vector<TbpNode>& parents = levels_data_[l];
        std::vector<TbpNode> children;
        children.reserve(parents.size() * sub.size());
        for (const TbpNode& p : parents)
            for (const auto& s : sub) {
                TbpNode c;
                for (int i = 0; i < 3; ++i) c.domain[i] = p.root_parameter(s[i]);
                // Subdivide the parent (not the root) over the local subtriangle [Sei89].
                c.patch = p.patch.subpatch(s[0], s[1], s[2]);
                c.box = c.patch.bounding_box();
                children.push_back(std::move(c));
            }
        levels_data_.push_back(std::move(children));
    }
}

std::vector<TbpHierarchy> build_hierarchies(const TbpSolid& solid, int levels, int lod) {
    validate(solid);
    std::vector<TbpHierarchy> out;
    out.reserve(solid.patches.size());
    for (const TbpPatch& p : solid.patches) out.emplace_back(p, levels, lod);
    return out;
}

}  // namespace trimkit::tbp
