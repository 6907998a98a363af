// Tests for tbp/intersect_patches.h (acceptance, issue 5): two flat patches
// crossing at a known line give one open component on that line within 1e-9;
// a cubic patch against a plane gives the curve found by sampling; a bump cut
// near its top gives one closed loop; Y junctions; pruning counts.
#include "tbp/intersect_patches.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "tbp/triangle_intersection.h"
#include "tbp_samples.h"

namespace trimkit::tbp {
namespace {

// A cubic over the triangle (0,0,0) (1,0,0) (0,1,0) with z = 6 h u v w (b111 raised by h).
TbpPatch bump(double h) {
    std::vector<Eigen::Vector3d> P;
    const Eigen::Vector3d a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    for (int i = 3; i >= 0; --i)
        for (int j = 3 - i; j >= 0; --j) {
            Eigen::Vector3d p = (i * a + j * b + (3 - i - j) * c) / 3;
            if (i == 1 && j == 1) p.z() = h;
            P.push_back(p);
        }
    return TbpPatch(3, P);
}

TEST(TriangleIntersection, CrossingAndDegenerateCases) {
    const Triangle3 t1{Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(2, 0, 0), Eigen::Vector3d(0, 2, 0)};
    const Triangle3 t2{Eigen::Vector3d(0.5, -1, -1), Eigen::Vector3d(0.5, 3, -1), Eigen::Vector3d(0.5, 0.5, 1)};
    Eigen::Vector3d p, q;
    ASSERT_TRUE(triangle_intersection(t1, t2, p, q));
    EXPECT_NEAR(p.z(), 0, 1e-15);
    EXPECT_NEAR(p.x(), 0.5, 1e-15);
    EXPECT_NEAR(std::abs(p.y() - q.y()), 1.5, 1e-15);  // x = 0.5 on t1: y from 0 to 1.5
    const Triangle3 coplanar{Eigen::Vector3d(0.1, 0.1, 0), Eigen::Vector3d(3, 0, 0), Eigen::Vector3d(0, 3, 0)};
    EXPECT_FALSE(triangle_intersection(t1, coplanar, p, q));
    const Triangle3 apart{Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 2), Eigen::Vector3d(0, 1, 1)};
    EXPECT_FALSE(triangle_intersection(t1, apart, p, q));
    // a vertex exactly on the other plane, edge crossing through it
    const Triangle3 touch{Eigen::Vector3d(0.5, 0.5, 0), Eigen::Vector3d(0.5, 0.5, 1), Eigen::Vector3d(1.5, 0.5, 1)};
    EXPECT_FALSE(triangle_intersection(t1, touch, p, q));
}

TEST(IntersectPatches, FlatPatchesCrossAtKnownLine) {
    // A: z = 0; B: the plane x = 0.3 + 0.1 y, spanning z in [-1, 1].
    const TbpPatch a = test::flat_patch({-1, -1, 0}, {2, -1, 0}, {-1, 2, 0});
    const TbpPatch b = test::flat_patch({0.3 - 0.15, -1.5, -1}, {0.3 + 0.15, 1.5, -1}, {0.3, 0, 1});
    for (int levels : {1, 2, 3}) {
        const TbpHierarchy ha(a, levels, 2), hb(b, levels, 2);
        const PatchIntersection r = intersect_patches(ha, hb);
        ASSERT_EQ(r.components.size(), 1u) << levels;
        EXPECT_FALSE(r.components[0].closed);
        EXPECT_TRUE(r.junctions.empty());
        for (const IntersectionPoint& p : r.components[0].points) {
            EXPECT_NEAR(p.position.z(), 0.0, 1e-9);
            EXPECT_NEAR(p.position.x() - 0.3 - 0.1 * p.position.y(), 0.0, 1e-9);
            EXPECT_LT((a.evaluate(p.uvw_a) - p.position).norm(), 1e-9);
            EXPECT_LT((b.evaluate(p.uvw_b) - p.position).norm(), 1e-9);
        }
        // the line runs from B's edge at y = -0.75 to A's edge x + y = 1, at y = 0.7 / 1.1
        const auto& pts = r.components[0].points;
        EXPECT_NEAR(std::abs(pts.front().position.y() - pts.back().position.y()), 0.75 + 0.7 / 1.1, 1e-9);
        const PatchIntersection brute = intersect_patches(ha, hb, false);
        EXPECT_EQ(brute.segments.size(), r.segments.size());
        EXPECT_LT(r.stats.triangle_tests, brute.stats.triangle_tests);
        std::printf("flat/flat levels %d lod 2: %lld box tests, %lld triangle tests (without hierarchy %lld)\n",
                    levels, r.stats.box_tests, r.stats.triangle_tests, brute.stats.triangle_tests);
    }
}

TEST(IntersectPatches, CubicAgainstPlaneMatchesSampling) {
    // A curved cubic; B: the plane z = 0.05 (a big flat triangle).
    const TbpPatch a = bump(0.6);  // z = 3.6 u v w, max 0.1333
    const double c = 0.05;
    const TbpPatch b = test::flat_patch({-1, -1, c}, {3, -1, c}, {-1, 3, c});
    double previous = 1e9;
    for (int levels : {1, 2, 3}) {
        const TbpHierarchy ha(a, levels, 3), hb(b, 0, 3);
        const PatchIntersection r = intersect_patches(ha, hb);
        ASSERT_EQ(r.components.size(), 1u);
        EXPECT_TRUE(r.components[0].closed);
        // deviation of the exact surface at the component's parameters from the plane
        double worst = 0;
        for (const IntersectionPoint& p : r.components[0].points) worst = std::max(worst, std::abs(a.evaluate(p.uvw_a).z() - c));
        // sampling: every sign change of z - c on a fine grid lies near the polyline
        const int N = 200;
        double far = 0;
        for (int i = 0; i < N; ++i)
            for (int j = 0; i + j < N; ++j) {
                const Eigen::Vector3d t0(double(i) / N, double(j) / N, double(N - i - j) / N);
                const Eigen::Vector3d t1(double(i + 1) / N, double(j) / N, double(N - i - j - 1) / N);
                const double z0 = a.evaluate(t0).z() - c, z1 = a.evaluate(t1).z() - c;
                if ((z0 < 0) == (z1 < 0)) continue;
                const Eigen::Vector3d x = a.evaluate(t0 + (t1 - t0) * (z0 / (z0 - z1)));
                double best = 1e9;
                const auto& pts = r.components[0].points;
                for (std::size_t k = 0; k < pts.size(); ++k) {  // distance to the closed polyline
                    const Eigen::Vector3d p = pts[k].position, q = pts[(k + 1) % pts.size()].position;
                    const double t = std::clamp((x - p).dot(q - p) / (q - p).squaredNorm(), 0.0, 1.0);
                    best = std::min(best, (p + t * (q - p) - x).norm());
                }
                far = std::max(far, best);
            }
        std::printf("cubic/plane levels %d lod 3: %zu points, |z - c| <= %.3g, sampled curve within %.3g\n", levels,
                    r.components[0].points.size(), worst, far);
        EXPECT_LT(worst, previous);
        EXPECT_LT(far, 0.5 / std::pow(4.0, levels));
        previous = worst;
    }
}

TEST(BuildComponents, YJunctionAndLoop) {
    PatchIntersection r;
    auto seg = [&](Eigen::Vector3d p, Eigen::Vector3d q) {
        IntersectionSegment s;
        s.ends[0].position = p;
        s.ends[1].position = q;
        r.segments.push_back(s);
    };
    const Eigen::Vector3d o(0, 0, 0), x(1, 0, 0), y(0, 1, 0), z(0, 0, 1), x2(2, 0, 0);
    seg(o, x), seg(x, x2), seg(o, y), seg(z, o), seg(x, o);  // the last duplicates the first
    seg(Eigen::Vector3d(5, 0, 0), Eigen::Vector3d(6, 0, 0));  // loop far away
    seg(Eigen::Vector3d(6, 0, 0), Eigen::Vector3d(5, 1, 0));
    seg(Eigen::Vector3d(5, 1, 0), Eigen::Vector3d(5, 0, 1e-13));  // closes within tolerance
    build_components(r, 1e-10);
    EXPECT_EQ(r.segments.size(), 7u);
    ASSERT_EQ(r.junctions.size(), 1u);
    EXPECT_EQ(r.junctions[0], o);
    int open = 0, closed = 0;
    for (const auto& c : r.components) (c.closed ? closed : open)++;
    EXPECT_EQ(open, 3);
    EXPECT_EQ(closed, 1);
}

TEST(IntersectSolids, TiltedSquareThroughCubeIsOneClosedLoopOnTheFaces) {
    // z = 0.4 + 0.1 x + 0.05 y over [-0.6, 1.7] x [-0.45, 1.55]: crosses the four side faces of the unit cube
    auto p = [](double x, double y) { return Eigen::Vector3d(x, y, 0.4 + 0.1 * x + 0.05 * y); };
    TbpSolid square;
    test::add_quad(square.patches, p(-0.6, -0.45), p(1.7, -0.45), p(1.7, 1.55), p(-0.6, 1.55));
    const auto hs = build_hierarchies(square, 2, 3), hc = build_hierarchies(test::box_solid(), 2, 3);
    const PatchIntersection r = intersect_solids(hs, hc);
    ASSERT_EQ(r.components.size(), 1u);
    EXPECT_TRUE(r.components[0].closed);
    EXPECT_TRUE(r.junctions.empty());
    for (const IntersectionPoint& q : r.components[0].points) {
        double d = INFINITY;
        for (int a = 0; a < 3; ++a) d = std::min({d, std::abs(q.position[a]), std::abs(q.position[a] - 1)});
        EXPECT_LT(d, 1e-9);
    }
    const PatchIntersection all = intersect_solids(hs, hc, false);
    EXPECT_EQ(all.stats.segments, r.stats.segments);
    EXPECT_LT(r.stats.triangle_tests, all.stats.triangle_tests);
    EXPECT_EQ(all.components.size(), 1u);
}

}  // namespace
}  // namespace trimkit::tbp
