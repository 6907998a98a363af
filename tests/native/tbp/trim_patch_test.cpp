// Tests for tbp/trim_patch.h (acceptance, issue 5): a flat square (two flat
// cubic TBPs) crossing the unit cube, trimmed with keep = outside, keeps the
// square's area minus the cube's section within 1e-6 relative, and its new
// boundary lies on the cube's faces within 1e-9; keep = inside keeps the
// section; untrimmed sub-TBPs and states.
#include "tbp/trim_patch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "mesh/open_edges.h"
#include "tbp/polygonize.h"
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

#include "tbp/from_mesh.h"

namespace trimkit::tbp {
namespace {

// Distance from x to the solid's surface: nearest sample of a fine pattern,
// then Gauss-Newton on that patch and its runners-up (clamped to the domain).
double distance_to_solid(const TbpSolid& s, const Eigen::Vector3d& x) {
    const DomainPattern pat = triangle_pattern(12);
    std::vector<std::pair<double, std::pair<int, int>>> best;
    for (std::size_t p = 0; p < s.patches.size(); ++p)
        for (std::size_t q = 0; q < pat.points.size(); ++q)
            best.push_back({(s.patches[p].evaluate(pat.points[q]) - x).norm(), {int(p), int(q)}});
    std::partial_sort(best.begin(), best.begin() + 6, best.end());
    double d = INFINITY;
    for (int c = 0; c < 6; ++c) {
        const TbpPatch& b = s.patches[best[c].second.first];
        Eigen::Vector3d t = pat.points[best[c].second.second];
        for (int it = 0; it < 30; ++it) {
            Eigen::Matrix<double, 3, 2> J;
            J.col(0) = b.derivative_u(t);
            J.col(1) = b.derivative_v(t);
            const Eigen::Vector2d step = (J.transpose() * J).ldlt().solve(J.transpose() * (x - b.evaluate(t)));
            t.head<2>() += step;
            t = t.cwiseMax(0.0);
            t[2] = 1 - t[0] - t[1];
            if (t[2] < 0) t.head<2>() /= (t[0] + t[1]), t[2] = 0;
        }
        d = std::min(d, (b.evaluate(t) - x).norm());
    }
    return d;
}

TEST(TrimPatch, CurvedPatchAgainstPnIcosphereConverges) {
    const TbpSolid sphere = pn_triangles(test::icosphere(1));
    std::vector<Eigen::Vector3d> P;
    const Eigen::Vector3d a(-3, -2, 0.2), b(3, -2, 0.2), c(0, 3, 0.2);
    for (int i = 3; i >= 0; --i)
        for (int j = 3 - i; j >= 0; --j) {
            Eigen::Vector3d p = (i * a + j * b + (3 - i - j) * c) / 3;
            if (i == 1 && j == 1) p.z() += 0.6;  // z = 0.2 + 3.6 u v w
            P.push_back(p);
        }
    const TbpPatch target(3, P);
    std::vector<double> areas, distances;
    const int settings[][2] = {{1, 1}, {1, 3}, {2, 2}, {2, 3}, {3, 2}};
    for (const auto& lv : settings) {
        TrimOptions o;
        o.levels = lv[0];
        o.lod = lv[1];
        const TrimResult r = trim_patch(target, sphere, o);
        double worst = 0;
        int cut = 0;
        for (const TrimBoundary& bd : r.boundaries)
            for (std::size_t k = 0; k < bd.points.size(); ++k)
                if (bd.on_cut[k]) ++cut, worst = std::max(worst, distance_to_solid(sphere, bd.points[k]));
        areas.push_back(mesh::surface_area(r.mesh));
        distances.push_back(worst);
        std::printf("curved x PN icosphere levels %d lod %d: remaining area %.9f, boundary to tool <= %.3g "
                    "(%d cut edges, %zu sub-TBPs, %lld triangle tests, %.3f s)\n",
                    lv[0], lv[1], areas.back(), worst, cut, r.untrimmed.size(), r.stats.intersection.triangle_tests,
                    r.stats.seconds);
        EXPECT_GT(cut, 0);
        EXPECT_EQ(r.boundaries.size(), 2u);  // the patch's outline and the hole
    }
    // converging: later changes are smaller than the first, the boundary approaches the tool
    EXPECT_LT(std::abs(areas[4] - areas[3]), std::abs(areas[1] - areas[0]));
    EXPECT_LT(distances.back(), distances.front());
    EXPECT_LT(distances.back(), 2e-3);
}

}  // namespace
}  // namespace trimkit::tbp
