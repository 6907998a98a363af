#include "tess/simplify_trim_polyline.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "geom/nurbs_surface.h"
#include "mesh/deadline.h"

namespace trimkit::tess {
namespace {

PolylinePoint at(double u, double v, double z) {
    PolylinePoint p;
    p.uv = {u, v};
    p.xyz = {u, v, z};
    p.t = u;
    return p;
}

TEST(SimplifyTrimPolyline, RemovesCollinearPointsKeepsEnds) {
    TrimPolyline line;
    for (int k = 0; k <= 10; ++k) line.points.push_back(at(k / 10.0, 0.5, 0.0));
    simplify_trim_polyline(&line, 1e-6, 1.0);
    ASSERT_EQ(line.points.size(), 2u);
    EXPECT_EQ(line.points.front().t, 0.0);
    EXPECT_EQ(line.points.back().t, 1.0);
}

TEST(SimplifyTrimPolyline, KeepsEveryOriginalPointWithinBudget) {
    // A bump of height 1e-3 in z: a 2e-3 budget drops it, 5e-4 keeps its peak.
    TrimPolyline bump;
    for (int k = 0; k <= 20; ++k)
        bump.points.push_back(at(k / 20.0, 0.0, 1e-3 * std::sin(3.14159265358979 * k / 20.0)));
    TrimPolyline loose = bump, tight = bump;
    simplify_trim_polyline(&loose, 2e-3, 1.0);
    EXPECT_EQ(loose.points.size(), 2u);
    simplify_trim_polyline(&tight, 5e-4, 1.0);
    EXPECT_GT(tight.points.size(), 2u);
    // Every original point is within the budget of the simplified polyline.
    for (const PolylinePoint& p : bump.points) {
        double d = INFINITY;
        for (size_t i = 0; i + 1 < tight.points.size(); ++i) {
            const Eigen::Vector3d a = tight.points[i].xyz, b = tight.points[i + 1].xyz;
            const double s = std::clamp((p.xyz - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
            d = std::min(d, (p.xyz - a - s * (b - a)).norm());
        }
        EXPECT_LE(d, 5e-4);
    }
}

TEST(SimplifyTrimPolyline, UvDeviationCountsThroughSurfaceSpeed) {
    // Straight in 3D but bent in uv: a fast surface keeps the bend.
    TrimPolyline bent;
    bent.points = {at(0, 0, 0), at(0.5, 0.01, 0), at(1, 0, 0)};
    bent.points[1].xyz = {0.5, 0.0, 0.0};
    TrimPolyline slow = bent, fast = bent;
    simplify_trim_polyline(&slow, 1e-3, 0.01);
    EXPECT_EQ(slow.points.size(), 2u);
    simplify_trim_polyline(&fast, 1e-3, 10.0);
    EXPECT_EQ(fast.points.size(), 3u);
}

// A zig-zag of 4001 points 0.01 apart along x and 0.5 across, on the plane z = 0
// (each segment's hull its own two ends): against the hulls no point can go, and the
// ranges split a point at a time from the peaks inwards. With a deadline that has
// passed, the simplification stops with DeadlineExceeded instead of finishing.
TEST(SimplifyTrimPolyline, HullRangesStopAtTheDeadline) {
    const geom::NurbsSurface plane(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2,
                                   {{0, 0, 0}, {0, 1, 0}, {1, 0, 0}, {1, 1, 0}});
    TrimPolyline zigzag;
    std::vector<SegmentHull> hulls;
    constexpr int n = 4000;
    for (int k = 0; k <= n; ++k) {
        PolylinePoint p = at(0.01 * k, 0.5 + (k % 2 ? 0.25 : -0.25), 0.0);
        zigzag.points.push_back(p);
        if (k > 0) hulls.push_back({{zigzag.points[k - 1].xyz, p.xyz}, {zigzag.points[k - 1].uv, p.uv}});
    }
    TrimPolyline all = zigzag;
    simplify_trim_polyline(&all, hulls, plane, 1e-3, 1.0);
    EXPECT_EQ(all.points.size(), std::size_t(n + 1));
    mesh::Deadline passed(1e-6);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    EXPECT_THROW(simplify_trim_polyline(&zigzag, hulls, plane, 1e-3, 1.0, &passed), mesh::DeadlineExceeded);
}

}  // namespace
}  // namespace trimkit::tess
