// remove_crossings: a crossing goes where the triangles that replace it keep the bound.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "tess/remove_crossings.h"
#include "tess/tessellate_face.h"
#include "tess/trim_cells.h"
#include "tess/kd_subdivision.h"
#include "surface_test_support.h"

namespace trimkit::tess {
namespace {

using test::paraboloid;

// Two cells [0, 0.5] x [0, 1] and [0.5, 1] x [0, 1], trimmed to v >= 0.3 by the chord
// from (0, 0.3) to (1, 0.3), which crosses their common side at vertex 1.
CrossingMesh two_cells_cut_by_a_chord(const geom::NurbsSurface& S) {
    CrossingMesh m;
    m.uv = {{0, 0.3}, {0.5, 0.3}, {1, 0.3}, {1, 1}, {0.5, 1}, {0, 1}};
    for (const auto& p : m.uv) m.xyz.push_back(S.evaluate(p.x(), p.y()));
    m.xyz[1] = 0.5 * (m.xyz[0] + m.xyz[2]);  // on the 3D chord, as trim_cells puts it
    m.crossing = {0, 1, 0, 0, 0, 0};
    m.triangles = {{0, 1, 4}, {0, 4, 5}, {1, 2, 3}, {1, 3, 4}};
    m.trim_edges = {{0, 1}, {1, 2}};
    return m;
}

double uv_area(const CrossingMesh& m) {
    double area = 0.0;
    for (const auto& t : m.triangles) {
        const Eigen::Vector2d e1 = m.uv[t[1]] - m.uv[t[0]], e2 = m.uv[t[2]] - m.uv[t[0]];
        area += 0.5 * (e1.x() * e2.y() - e1.y() * e2.x());
    }
    return area;
}

bool uses(const CrossingMesh& m, int v) {
    for (const auto& t : m.triangles)
        if (std::find(t.begin(), t.end(), v) != t.end()) return true;
    return false;
}

TEST(RemoveCrossings, OnAPlaneTheCrossingGoesAndTheRegionStays) {
    const geom::NurbsSurface S = paraboloid(1, true);
    CrossingMesh m = two_cells_cut_by_a_chord(S);
    EXPECT_EQ(remove_crossings(S, nullptr, ErrorMode::kGuaranteed, m, 1e-9, 1e-9), 1);
    EXPECT_EQ(m.triangles.size(), 3u);  // the crossing's fan of 3 becomes 2
    EXPECT_FALSE(uses(m, 1));
    ASSERT_EQ(m.trim_edges.size(), 1u);
    EXPECT_EQ(m.trim_edges[0], (std::array<int, 2>{0, 2}));
    EXPECT_NEAR(uv_area(m), 0.7, 1e-12);
}

// Every triangulation of the ring 2 3 4 0 without vertex 1 has a triangle on the chord
// 0 2 reaching v = 1: its box is 1 x 0.7, within (2 * 1 + 2 * 0.49) / 8 = 0.3725 of S
// (block_error.h; the control net's bilinear bound of the piece, at least the 0.5 of
// u^2's net alone, is larger) and no less. So the crossing goes at 1.01 times that and
// stays at 0.99 times.
TEST(RemoveCrossings, ACrossingStaysWhereTheMergedTrianglesWouldLeaveTheBound) {
    const geom::NurbsSurface S = paraboloid();
    const double bound = (2.0 * 1.0 + 2.0 * 0.49) / 8.0;
    CrossingMesh kept = two_cells_cut_by_a_chord(S);
    EXPECT_EQ(remove_crossings(S, nullptr, ErrorMode::kGuaranteed, kept, 0.99 * bound, 0.99 * bound), 0);
    EXPECT_EQ(kept.triangles, two_cells_cut_by_a_chord(S).triangles);
    EXPECT_EQ(kept.trim_edges.size(), 2u);
    CrossingMesh removed = two_cells_cut_by_a_chord(S);
    EXPECT_EQ(remove_crossings(S, nullptr, ErrorMode::kGuaranteed, removed, 1.01 * bound, 1.01 * bound), 1);
    EXPECT_EQ(removed.triangles.size(), 3u);
    // The total bound counts the vertices' offsets from S too: a trim point moved off S
    // by 0.1 leaves no room at 1.01 times the bound.
    CrossingMesh off = two_cells_cut_by_a_chord(S);
    off.xyz[0].z() += 0.1;
    EXPECT_EQ(remove_crossings(S, nullptr, ErrorMode::kGuaranteed, off, 1.01 * bound, 1.01 * bound), 0);
    EXPECT_EQ(remove_crossings(S, nullptr, ErrorMode::kGuaranteed, off, 1.01 * bound, 1.01 * bound + 0.1), 1);
}

// A trim point is never removed, even on the chord of its neighbours.
TEST(RemoveCrossings, TrimPointsStay) {
    const geom::NurbsSurface S = paraboloid(1, true);
    CrossingMesh m = two_cells_cut_by_a_chord(S);
    m.crossing[1] = 0;
    EXPECT_EQ(remove_crossings(S, nullptr, ErrorMode::kGuaranteed, m, 1.0, 1.0), 0);
    EXPECT_EQ(m.triangles.size(), 4u);
}

size_t boundary_points(const mesh::Mesh& m) {
    std::set<int> boundary;
    for (const auto& e : m.edges)
        if (e.flags & mesh::kFaceBoundary) boundary.insert({e.v0, e.v1});
    return boundary.size();
}

// A whole face: a disc trimmed from a paraboloid of 4 x 4 spans. With its trim points
// marked keep_crossings, the face's boundary has every trim point and every crossing
// trim_cells makes on the same cells; without, fewer, and the mesh stays within T of S
// at the same (u,v).
TEST(RemoveCrossings, AFaceKeepsFewerBoundaryPointsWithinTheTolerance) {
    const geom::NurbsSurface S = paraboloid(4);
    TessellationOptions options;
    options.tolerance = 0.004;
    std::vector<TrimPolygon> loops = {test::circle_loop(S, 0.5, 0.5, 0.4, 96, true)};
    const mesh::Mesh reduced = tessellate_face(test::face_of(S), loops, options, 0);
    for (PolylinePoint& p : loops[0].points) p.keep_crossings = true;
    const mesh::Mesh kept = tessellate_face(test::face_of(S), loops, options, 0);

    Eigen::AlignedBox2d box;
    for (const auto& p : loops[0].points) box.extend(p.uv);
    box.min() -= Eigen::Vector2d::Constant(1e-9 * 0.8);  // tessellate_face's margin
    box.max() += Eigen::Vector2d::Constant(1e-9 * 0.8);
    const CellGrid grid = kd_subdivision(S, box, interior_tolerance(options), surface_tolerance(options),
                                         options.tolerance, loops, options.mode);
    const TrimmedCells trimmed = trim_cells(grid, loops);
    const auto crossings = std::count_if(trimmed.vertices.begin(), trimmed.vertices.end(), [](const TrimmedVertex& v) {
        return v.on_trim && std::abs((v.uv - Eigen::Vector2d(0.5, 0.5)).norm() - 0.4) > 1e-12;
    });
    ASSERT_GT(crossings, 8);
    EXPECT_EQ(boundary_points(kept), loops[0].points.size() + static_cast<size_t>(crossings));
    EXPECT_LT(boundary_points(reduced), boundary_points(kept));
    EXPECT_GE(boundary_points(reduced), loops[0].points.size());
    EXPECT_LT(reduced.triangles.size(), kept.triangles.size());
    EXPECT_LE(test::parametric_deviation(reduced, S), options.tolerance);
}

}  // namespace
}  // namespace trimkit::tess
