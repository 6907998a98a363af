// Tests for tbp/trim_patch.h (acceptance, issue 5): a flat square (two flat
// cubic TBPs) crossing the unit cube, trimmed with keep = outside, keeps the
// square's area minus the cube's section within 1e-6 relative, and its new
// boundary lies on the cube's faces within 1e-9; keep = inside keeps the
// section; untrimmed sub-TBPs and states.
#include "tbp/trim_patch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "mesh/open_edges.h"
#include "tbp_samples.h"

namespace trimkit::tbp {
namespace {

// The tilted plane z = 0.4 + 0.1 x + 0.05 y over [x0,x1] x [y0,y1], as two flat cubic TBPs.
TbpSolid tilted_square(double x0, double x1, double y0, double y1) {
    auto p = [](double x, double y) { return Eigen::Vector3d(x, y, 0.4 + 0.1 * x + 0.05 * y); };
    TbpSolid s;
    test::add_quad(s.patches, p(x0, y0), p(x1, y0), p(x1, y1), p(x0, y1));
    return s;
}

double distance_to_unit_cube_surface(const Eigen::Vector3d& q) {
    double d = INFINITY;
    for (int a = 0; a < 3; ++a) d = std::min({d, std::abs(q[a]), std::abs(q[a] - 1)});
    return d;
}

TEST(TrimPatch, FlatSquareCrossingCubeKeepOutside) {
    const double factor = std::sqrt(1 + 0.1 * 0.1 + 0.05 * 0.05);
    const TbpSolid square = tilted_square(-0.6, 1.7, -0.45, 1.55);
    const TbpSolid cube = test::box_solid();
    for (int levels : {1, 2}) {
        for (Keep keep : {Keep::kOutside, Keep::kInside}) {
            TrimOptions o;
            o.levels = levels;
            o.lod = 3;
            o.keep = keep;
            std::vector<TrimResult> parts;
            const mesh::Mesh m = trim_solid(square, cube, o, &parts);
            mesh::validate(m);
            const double expected = keep == Keep::kOutside ? (2.3 * 2.0 - 1.0) * factor : factor;
            EXPECT_NEAR(mesh::surface_area(m) / expected, 1.0, 1e-6) << levels;
            double worst = 0;
            long long tri_tests = 0;
            int cut_edges = 0;
            for (const TrimResult& r : parts) {
                tri_tests += r.stats.intersection.triangle_tests;
                for (const TrimBoundary& b : r.boundaries)
                    for (std::size_t k = 0; k < b.points.size(); ++k) {
                        if (!b.on_cut[k]) continue;
                        ++cut_edges;
                        worst = std::max({worst, distance_to_unit_cube_surface(b.points[k]),
                                          distance_to_unit_cube_surface(b.points[(k + 1) % b.points.size()])});
                    }
            }
            EXPECT_GT(cut_edges, 0);
            EXPECT_LT(worst, 1e-9);
            std::printf("square x cube levels %d lod 3 keep %s: area %.15g (expected %.15g), boundary off cube <= %.3g, "
                        "%lld triangle tests, %.3f s\n",
                        levels, keep == Keep::kOutside ? "outside" : "inside", mesh::surface_area(m), expected, worst,
                        tri_tests, parts[0].stats.seconds + parts[1].stats.seconds);
        }
    }
}

TEST(TrimPatch, PatchAwayFromToolIsOneUntrimmedSubTbp) {
    const TbpSolid far_square = tilted_square(3, 4, 3, 4);
    TrimOptions o;
    o.levels = 1;
    o.lod = 1;
    const TrimResult r = trim_patch(far_square.patches[0], test::box_solid(), o);
    ASSERT_EQ(r.untrimmed.size(), 1u);
    EXPECT_EQ(r.untrimmed[0].level, 0);
    EXPECT_EQ(r.mesh.triangle_count(), 4u);
    EXPECT_EQ(r.stats.intersection.triangle_tests, 0);
    ASSERT_EQ(r.boundaries.size(), 1u);
    o.keep = Keep::kInside;
    EXPECT_EQ(trim_patch(far_square.patches[0], test::box_solid(), o).mesh.triangle_count(), 0u);
}

TEST(TrimPatch, HoleInTheMiddleGivesTwoLoops) {
    // a square much larger than the cube: the kept part has the section as a hole
    const TbpSolid big = tilted_square(-3, 4, -3, 4);
    TrimOptions o;
    o.levels = 2;
    o.lod = 2;
    std::vector<TrimResult> parts;
    trim_solid(big, test::box_solid(), o, &parts);
    int loops = 0;
    for (const auto& r : parts) loops += static_cast<int>(r.boundaries.size());
    EXPECT_GE(loops, 2);
    std::size_t sub = parts[0].untrimmed.size() + parts[1].untrimmed.size();
    EXPECT_GT(sub, 0u);
}

}  // namespace
}  // namespace trimkit::tbp
