// Tests for tbp/tbp_hierarchy.h: node counts (lod+1)^(2 levels), subdomains
// tile the domain with the root's orientation, every node reproduces the root
// patch over its subdomain, child boxes lie in their parent's box.
#include "tbp/tbp_hierarchy.h"

#include <gtest/gtest.h>

#include <random>

#include "geom/error.h"
#include "tbp_samples.h"

namespace trimkit::tbp {
namespace {

TbpPatch curved_cubic() {
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> c(-0.3, 0.3);
    std::vector<Eigen::Vector3d> P;
    for (int i = 3; i >= 0; --i)
        for (int j = 3 - i; j >= 0; --j) P.emplace_back(i + c(rng), j + c(rng), c(rng));
    return TbpPatch(3, P);
}

double signed_area(const std::array<Eigen::Vector3d, 3>& d) {
    const Eigen::Vector2d a = d[0].head<2>(), b = d[1].head<2>(), c = d[2].head<2>();
    const Eigen::Vector2d e = b - a, f = c - a;
    return 0.5 * (e.x() * f.y() - e.y() * f.x());
}

TEST(UniformSubtriangles, TileTheTriangleWithItsOrientation) {
    for (int m = 1; m <= 5; ++m) {
        const auto sub = uniform_subtriangles(m);
        ASSERT_EQ(static_cast<int>(sub.size()), m * m);
        double area = 0;
        for (const auto& s : sub) {
            EXPECT_NEAR(signed_area(s), 0.5 / (m * m), 1e-15);  // the unit domain in (u,v) has area 1/2, positive
            area += signed_area(s);
            for (const auto& p : s) EXPECT_NEAR(p.sum(), 1.0, 1e-15);
        }
        EXPECT_NEAR(area, 0.5, 1e-14);
    }
}

TEST(TbpHierarchy, NodeCountsAndSubdomainsReproduceRoot) {
    const TbpPatch root = curved_cubic();
    for (int lod : {0, 1, 3})
        for (int levels : {0, 1, 2}) {
            const TbpHierarchy h(root, levels, lod);
            long long expected = 1;
            for (int l = 0; l <= levels; ++l) {
                ASSERT_EQ(static_cast<long long>(h.level(l).size()), expected);
                double area = 0;
                for (std::size_t k = 0; k < h.level(l).size(); ++k) {
                    const TbpNode& n = h.node(l, static_cast<int>(k));
                    area += signed_area(n.domain);
                    const Eigen::Vector3d local(0.2, 0.3, 0.5);
                    EXPECT_LT((n.patch.evaluate(local) - root.evaluate(n.root_parameter(local))).norm(), 1e-12);
                    EXPECT_LT((n.base(0) - root.evaluate(n.domain[0])).norm(), 1e-12);
                    if (l > 0) {
                        const Eigen::AlignedBox3d& pb = h.node(l - 1, h.parent(static_cast<int>(k))).box;
                        EXPECT_TRUE(pb.min().cwiseMin(n.box.min()).isApprox(pb.min(), 1e-12) &&
                                    pb.max().cwiseMax(n.box.max()).isApprox(pb.max(), 1e-12));
                    }
                }
                EXPECT_NEAR(area, 0.5, 1e-12);
                expected *= (lod + 1) * (lod + 1);
            }
        }
}

TEST(TbpHierarchy, PaperLeafCount) {
    // [Garcia] Sec. 3: 3 levels with lod = 1 store 64 subpatches in the leaves.
    EXPECT_EQ(TbpHierarchy(curved_cubic(), 3, 1).leaves().size(), 64u);
}

TEST(TbpHierarchy, RejectsBadParameters) {
    EXPECT_THROW(TbpHierarchy(curved_cubic(), -1, 1), geom::InvalidInput);
    EXPECT_THROW(TbpHierarchy(curved_cubic(), 1, -1), geom::InvalidInput);
    EXPECT_THROW(TbpHierarchy(curved_cubic(), 12, 3), geom::InvalidInput);
    EXPECT_THROW(build_hierarchies(TbpSolid{}, 1, 1), geom::InvalidInput);
}

}  // namespace
}  // namespace trimkit::tbp
