#include "tess/repair_trim_loop.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geom/analytic_surfaces.h"
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

// bug22869_Spring.igs: the cut curve runs back up along the face's own seam edge
// (u = 0 here), crossing it, so the loop leaves lobes 2e-4 wide in (u,v) whose
// sides belong to two different neighbours. On a 10 x 10 plane they are 1e-3 wide:
// dropped below min_width, kept above it or without a surface.
TEST(RepairTrimLoop, ZeroWidthLobesAlongTheBoundaryAreDroppedOnTheSurface) {
    const geom::NurbsSurface plane = geom::plane_patch(Eigen::Vector3d::Zero(), 10.0 * Eigen::Vector3d::UnitX(),
                                                       10.0 * Eigen::Vector3d::UnitY(), 0, 1, 0, 1);
    auto on_plane = [&](double u, double v) {
        PolylinePoint p = at(u, v);
        p.xyz = plane.evaluate(u, v);
        return p;
    };
    const TrimPolygon loop{{on_plane(1, 0.4), on_plane(1, 1), on_plane(0, 1), on_plane(0, 0),
                            on_plane(2e-4, 0.1), on_plane(-2e-4, 0.2), on_plane(2e-4, 0.3), on_plane(0.5, 0.4)},
                           true};
    LoopRepairReport kept_report, dropped_report;
    const auto kept = repair_trim_loop(loop, kSnap, &kept_report);
    EXPECT_EQ(kept_report.crossings, 2);
    ASSERT_EQ(kept.size(), 3u);  // the main region and two lobes
    EXPECT_EQ(repair_trim_loop(loop, kSnap, nullptr, false, &plane, 1e-4).size(), 3u);  // lobes wider than that

    const auto dropped = repair_trim_loop(loop, kSnap, &dropped_report, false, &plane, 0.01);
    ASSERT_EQ(dropped.size(), 1u);
    EXPECT_EQ(dropped_report.dropped, 2);
    double lobes = 0.0;
    for (const auto& piece : kept) lobes += std::abs(signed_area(piece.points));
    lobes -= std::abs(signed_area(dropped[0].points));
    EXPECT_GT(lobes, 0.0);
    EXPECT_LT(lobes, 1e-4);  // what was dropped: the lobes' (u,v) area only
    EXPECT_TRUE(is_simple(dropped[0].points));
}

TEST(RepairTrimLoop, DegenerateLoopIsDropped) {
    LoopRepairReport report;
    EXPECT_TRUE(repair_trim_loop({{at(0, 0), at(1, 0), at(0, 0)}, true}, kSnap, &report).empty());
    EXPECT_EQ(report.dropped, 1);
}

}  // namespace
}  // namespace trimkit::tess
