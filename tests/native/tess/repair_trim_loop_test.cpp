#include "tess/repair_trim_loop.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tess/tess_test_cases.h"

namespace trimkit::tess {
namespace {

constexpr double kSnap = 1e-9;

PolylinePoint at(double u, double v, double t = 0.0) {
    PolylinePoint p;
    p.uv = {u, v};
    p.xyz = {u, v, 0.0};
    p.t = t;
    return p;
}

// True if no two non-adjacent segments of the closed polygon cross or touch.
bool is_simple(const std::vector<PolylinePoint>& P) {
    const int n = static_cast<int>(P.size());
    auto orient = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
        const Eigen::Vector2d r = b - a, s = c - a;
        return r.x() * s.y() - r.y() * s.x();
    };
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) {
            if (j == i + 1 || (i == 0 && j == n - 1)) continue;
            const auto &a = P[i].uv, &b = P[(i + 1) % n].uv, &c = P[j].uv, &d = P[(j + 1) % n].uv;
            if (orient(a, b, c) * orient(a, b, d) < 0 && orient(c, d, a) * orient(c, d, b) < 0)
                return false;
            if ((a - c).norm() < kSnap) return false;
        }
    return true;
}

TEST(RepairTrimLoop, JoinsCoedgesDroppingJointsAndSnappingGaps) {
    TrimPolyline bottom, right, top;
    bottom.points = {at(0, 0), at(0.5, 0), at(1, 0)};
    right.points = {at(1, 1e-12), at(1, 1)};   // within snap of (1, 0): joint dropped
    top.points = {at(1, 1), at(0, 1), at(0, 0)};  // closes onto the first point
    LoopRepairReport report;
    const TrimPolygon loop = join_trim_loop({bottom, right, top}, true, kSnap, &report);
    ASSERT_EQ(loop.points.size(), 5u);
    EXPECT_EQ(loop.points[2].uv, Eigen::Vector2d(1, 0));  // the earlier point is kept
    EXPECT_EQ(loop.points[4].uv, Eigen::Vector2d(0, 1));
    EXPECT_NEAR(report.max_gap, 1e-12, 1e-15);
    EXPECT_NEAR(signed_area(loop.points), 1.0, 1e-12);
}

TEST(RepairTrimLoop, OrientsOuterCcwAndHolesCw) {
    TrimPolygon cw{{at(0, 0), at(0, 1), at(1, 1), at(1, 0)}, true};
    LoopRepairReport report;
    auto out = repair_trim_loop(cw, kSnap, &report);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_TRUE(report.reoriented);
    EXPECT_NEAR(signed_area(out[0].points), 1.0, 1e-12);

    TrimPolygon ccw_hole{{at(0, 0), at(1, 0), at(1, 1), at(0, 1)}, false};
    LoopRepairReport hole_report;
    out = repair_trim_loop(ccw_hole, kSnap, &hole_report);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_TRUE(hole_report.reoriented);
    EXPECT_NEAR(signed_area(out[0].points), -1.0, 1e-12);
    EXPECT_FALSE(out[0].outer);

    // A reversed face's outer loop runs CW by face.h's convention: fixed silently.
    LoopRepairReport mirrored;
    out = repair_trim_loop(cw, kSnap, &mirrored, /*face_reversed=*/true);
    EXPECT_FALSE(mirrored.reoriented);
    EXPECT_NEAR(signed_area(out[0].points), 1.0, 1e-12);

    LoopRepairReport clean;
    repair_trim_loop({{at(0, 0), at(1, 0), at(1, 1), at(0, 1)}, true}, kSnap, &clean);
    EXPECT_FALSE(clean.changed());
}

TEST(RepairTrimLoop, SplitsFigureEightIntoTwoSimpleLoops) {
    // Lemniscate of Gerono u = cos θ, v = sin θ cos θ: lobes of area 2/3, crossing
    // at the origin between samples; the right lobe runs CCW, the left CW.
    const int N = 400;
    TrimPolygon eight;
    eight.outer = true;
    for (int k = 0; k < N; ++k) {
        const double th = 2 * test::kPi * (k + 0.5) / N;
        eight.points.push_back(at(std::cos(th), std::sin(th) * std::cos(th), th));
    }
    ASSERT_FALSE(is_simple(eight.points));
    LoopRepairReport report;
    const std::vector<TrimPolygon> loops = repair_trim_loop(eight, kSnap, &report);
    ASSERT_EQ(loops.size(), 2u);
    EXPECT_EQ(report.crossings, 1);
    EXPECT_EQ(report.split_loops, 1);
    for (const TrimPolygon& loop : loops) {
        EXPECT_TRUE(is_simple(loop.points));
        EXPECT_TRUE(loop.outer);
        EXPECT_NEAR(signed_area(loop.points), 2.0 / 3.0, 1e-3);  // both CCW now
        // The crossing point is a vertex of each loop.
        bool has_origin = false;
        for (const auto& p : loop.points) has_origin = has_origin || p.uv.norm() < 1e-12;
        EXPECT_TRUE(has_origin);
    }
}

TEST(RepairTrimLoop, DropsSpikeAndZeroAreaSliver) {
    // A square with a spike out and back along the same line at its top edge.
    TrimPolygon spiky{{at(0, 0), at(1, 0), at(1, 1), at(0.5, 1), at(0.5, 1.5), at(0.5, 1), at(0, 1)},
                      true};
    LoopRepairReport report;
    auto out = repair_trim_loop(spiky, kSnap, &report);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_EQ(report.dropped, 1);
    EXPECT_NEAR(signed_area(out[0].points), 1.0, 1e-12);
    EXPECT_TRUE(is_simple(out[0].points));

    // A spike that backtracks only part way: (0.5,1.5) -> (0.5,1.2) overlaps itself.
    TrimPolygon overlap{{at(0, 0), at(1, 0), at(1, 1), at(0.5, 1), at(0.5, 1.5), at(0.5, 1.2),
                         at(0.5, 1), at(0, 1)},
                        true};
    out = repair_trim_loop(overlap, kSnap);
    ASSERT_EQ(out.size(), 1u);
    EXPECT_NEAR(signed_area(out[0].points), 1.0, 1e-12);
}

TEST(RepairTrimLoop, DegenerateLoopIsDropped) {
    LoopRepairReport report;
    EXPECT_TRUE(repair_trim_loop({{at(0, 0), at(1, 0), at(0, 0)}, true}, kSnap, &report).empty());
    EXPECT_EQ(report.dropped, 1);
}

}  // namespace
}  // namespace trimkit::tess
