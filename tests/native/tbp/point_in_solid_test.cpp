// Tests for tbp/point_in_solid.h (acceptance, issue 5): the unit cube of 12
// flat TBPs classifies 10,000 random points right, including points within
// 1e-9 of its faces, edges and corners; points on the surface are kBoundary;
// box inclusion.
#include "tbp/point_in_solid.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include "tbp_samples.h"

namespace trimkit::tbp {
namespace {

bool in_unit_cube(const Eigen::Vector3d& p) { return (p.array() > 0).all() && (p.array() < 1).all(); }

TEST(PointInSolid, UnitCubeRandomAndNearFacePoints) {
    const TbpSolid cube = test::box_solid();
    for (int levels : {0, 1}) {
        const std::vector<TbpHierarchy> h = build_hierarchies(cube, levels, 2);
        std::mt19937 rng(11 + levels);
        std::uniform_real_distribution<double> u(-0.5, 1.5), f(0.0, 1.0);
        std::uniform_int_distribution<int> axis(0, 2), side(0, 1), sign(0, 1);
        PointInSolidStats stats;
        int wrong = 0, near = 0;
        for (int n = 0; n < 10000; ++n) {
            Eigen::Vector3d p(u(rng), u(rng), u(rng));
            if (n % 2) {  // within 1e-9 of a face (about 1 in 10 of these also near an edge)
                p = Eigen::Vector3d(f(rng), f(rng), f(rng));
                const int a = axis(rng);
                p[a] = side(rng) + (sign(rng) ? 1e-9 : -1e-9);
                if (n % 20 == 1) p[(a + 1) % 3] = side(rng) + (sign(rng) ? 1e-9 : -1e-9);
                ++near;
            }
            const Containment c = point_in_solid(h, p, &stats);
            const Containment expected = in_unit_cube(p) ? Containment::kInside : Containment::kOutside;
            if (c != expected) ++wrong;
        }
        EXPECT_EQ(wrong, 0);
        std::printf("cube levels %d: 10000 points (%d within 1e-9 of a face), %d wrong; %lld box tests, %lld triangle tests, "
                    "%lld rays rejected\n", levels, near, wrong, stats.box_tests, stats.triangle_tests, stats.rejected_rays);
    }
}

TEST(PointInSolid, SurfacePointsAreBoundaryAndCornersWork) {
    const std::vector<TbpHierarchy> h = build_hierarchies(test::box_solid(), 1, 1);
    EXPECT_EQ(point_in_solid(h, {0.3, 0.4, 1.0}), Containment::kBoundary);
    EXPECT_EQ(point_in_solid(h, {0.5, 0.5, 0.5}), Containment::kInside);  // on diagonals of the face triangulation
    EXPECT_EQ(point_in_solid(h, {1 - 1e-9, 1 - 1e-9, 1 - 1e-9}), Containment::kInside);
    EXPECT_EQ(point_in_solid(h, {1 + 1e-9, 1 - 1e-9, 1 - 1e-9}), Containment::kOutside);
    EXPECT_EQ(point_in_solid(h, {-1e-9, -1e-9, -1e-9}), Containment::kOutside);
}

TEST(PointInSolid, ScaleInvariant) {
    for (double s : {1e-6, 1e6}) {
        const std::vector<TbpHierarchy> h =
            build_hierarchies(test::box_solid(Eigen::Vector3d::Constant(s), Eigen::Vector3d::Constant(2 * s)), 1, 1);
        EXPECT_EQ(point_in_solid(h, Eigen::Vector3d::Constant(1.5 * s)), Containment::kInside);
        EXPECT_EQ(point_in_solid(h, Eigen::Vector3d(1.5 * s, 1.5 * s, (2 + 1e-9) * s)), Containment::kOutside);
    }
}

TEST(BoxInSolid, InsideOutsideAndCrossing) {
    const std::vector<TbpHierarchy> h = build_hierarchies(test::box_solid(), 2, 1);
    EXPECT_EQ(box_in_solid(h, Eigen::AlignedBox3d(Eigen::Vector3d::Constant(0.3), Eigen::Vector3d::Constant(0.6))),
              Containment::kInside);
    EXPECT_EQ(box_in_solid(h, Eigen::AlignedBox3d(Eigen::Vector3d::Constant(1.3), Eigen::Vector3d::Constant(1.6))),
              Containment::kOutside);
    EXPECT_EQ(box_in_solid(h, Eigen::AlignedBox3d(Eigen::Vector3d::Constant(0.8), Eigen::Vector3d::Constant(1.2))),
              Containment::kBoundary);
}

}  // namespace
}  // namespace trimkit::tbp
