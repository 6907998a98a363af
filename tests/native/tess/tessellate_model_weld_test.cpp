// Regressions of issue 3 for joining faces: shared edges give a closed mesh (a cube
// of six faces: Euler characteristic 2), the result does not depend on the thread
// count, a plate thinner than the tolerance keeps all its faces (bug33327.igs), and
// meshes of files whose check measured wrongly (projection stuck at a seam, at a C0
// crease, or started from another face's uv) are within the tolerance.
// Joining moves points by 0.1 T at most, and loose models stay within T at coarse
// tolerances.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include "mesh/mesh.h"
#include "geom/model.h"
#include "io/read_model.h"
#include "geom/flatten_instances.h"
#include "geom/face.h"
#include "geom/select_faces.h"
#include "mesh/open_edges.h"
#include "tess/measure_deviation.h"
#include "tess/snap_boundary_vertices.h"
#include "tess/tessellate_model.h"
#include "tess/surface_test_support.h"
#include "test_support.h"

namespace trimkit::tess {
namespace {

constexpr double kRelativeTolerance = 1e-3;  // issue 3's acceptance tolerance
constexpr double kAreaRatioBand = 2e-3;

Eigen::Vector3d corner(int k) { return {double(k & 1), double((k >> 1) & 1), double((k >> 2) & 1)}; }

// The unit cube: six bilinear faces, each given by its corners counter-clockwise
// seen from outside, S(0,0), S(1,0), S(1,1), S(0,1); twelve shared edges, each
// running from its smaller corner to its larger.
geom::Model cube() {
    const std::array<std::array<int, 4>, 6> faces{{{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                                   {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}}};
    const std::array<Eigen::Vector2d, 4> uv{Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0),
                                            Eigen::Vector2d(1, 1), Eigen::Vector2d(0, 1)};
    geom::Model model;
    std::map<std::pair<int, int>, int> edge_of;
    for (const auto& c : faces) {
        geom::Face face;
        face.surface = geom::NurbsSurface(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2,
                                          {corner(c[0]), corner(c[3]), corner(c[1]), corner(c[2])});
        geom::Loop loop;
        loop.outer = true;
        for (int k = 0; k < 4; ++k) {
            const int a = c[k], b = c[(k + 1) % 4];
            const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
            if (!edge_of.count(key)) {
                geom::Edge edge;
                edge.start = corner(key.first);
                edge.end = corner(key.second);
                edge_of[key] = static_cast<int>(model.edges.size());
                model.edges.push_back(edge);
            }
            geom::Coedge coedge;
            coedge.curve = geom::NurbsCurve2d(1, {0, 0, 1, 1}, {uv[k], uv[(k + 1) % 4]});
            coedge.edge = edge_of[key];
            coedge.edge_reversed = a > b;
            loop.coedges.push_back(coedge);
        }
        face.loops.push_back(loop);
        model.faces.push_back(face);
    }
    return model;
}

// V - E + F of the mesh's topology by position.
long euler_characteristic(const mesh::Mesh& m) {
    const std::vector<std::int32_t> group = position_groups(m);
    std::set<std::int32_t> vertices;
    std::set<std::pair<std::int32_t, std::int32_t>> edges;
    for (const auto& t : position_triangles(m, group))
        for (int k = 0; k < 3; ++k) {
            vertices.insert(t[k]);
            edges.insert({std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3])});
        }
    return static_cast<long>(vertices.size()) - static_cast<long>(edges.size()) +
           static_cast<long>(m.triangles.size());
}

TEST(TessellateModelWeld, CubeWithSharedEdgesIsClosed) {
    const geom::Model model = cube();
    TessellationOptions options;
    options.tolerance = 1e-3;
    options.threads = 1;
    const TessellationResult r = tessellate_model(model, options);
    EXPECT_TRUE(r.failed_faces.empty());
    EXPECT_EQ(r.faces_meshed, 6);
    EXPECT_EQ(r.open_edges, 0u);
    EXPECT_EQ(count_position_open_edges(r.mesh), 0u);
    EXPECT_EQ(euler_characteristic(r.mesh), 2);
    EXPECT_NEAR(mesh::surface_area(r.mesh), 6.0, 1e-12);
}

// The square [x0, x0 + 1] x [0, 1] in z = 0 as one bilinear face with four edges of
// its own, appended to `model` as a body of its own.
void add_square_part(geom::Model& model, double x0) {
    const Eigen::Vector3d c[4] = {{x0, 0, 0}, {x0 + 1, 0, 0}, {x0 + 1, 1, 0}, {x0, 1, 0}};
    const std::array<Eigen::Vector2d, 4> uv{Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0),
                                            Eigen::Vector2d(1, 1), Eigen::Vector2d(0, 1)};
    geom::Face face;
    face.surface = geom::NurbsSurface(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2, {c[0], c[3], c[1], c[2]});
    geom::Loop loop;
    loop.outer = true;
    for (int k = 0; k < 4; ++k) {
        geom::Edge edge;
        edge.start = c[k];
        edge.end = c[(k + 1) % 4];
        geom::Coedge coedge;
        coedge.curve = geom::NurbsCurve2d(1, {0, 0, 1, 1}, {uv[k], uv[(k + 1) % 4]});
        coedge.edge = static_cast<int>(model.edges.size());
        model.edges.push_back(edge);
        loop.coedges.push_back(coedge);
    }
    face.loops.push_back(loop);
    model.bodies.push_back({"square " + std::to_string(model.bodies.size()), {static_cast<int>(model.faces.size())}, false});
    model.faces.push_back(face);
}

// Two parts that touch (a nut on a bracket) are not joined to each other: each keeps
// its own boundary, as when it is meshed alone. Joined across the parts, the squares'
// common side x = 1 was welded shut (6 open edges instead of 8), and on
// as1-oc-214-mat.stp the nut's points snapped onto the bracket's left T-junctions
// inside the bracket.
TEST(TessellateModelWeld, PartsThatTouchAreJoinedEachOnItsOwn) {
    TessellationOptions options;
    options.tolerance = 1e-3;
    options.threads = 1;
    geom::Model one;
    add_square_part(one, 0.0);
    const TessellationResult alone = tessellate_model(one, options);
    ASSERT_EQ(alone.open_edges, 4u);  // two triangles, four boundary sides
    geom::Model two = one;
    add_square_part(two, 1.0);
    const TessellationResult both = tessellate_model(two, options);
    EXPECT_TRUE(both.failed_faces.empty());
    EXPECT_EQ(both.open_edges, 2 * alone.open_edges);
    EXPECT_EQ(both.mesh.triangle_count(), 2 * alone.mesh.triangle_count());
    EXPECT_NEAR(mesh::surface_area(both.mesh), 2.0, 1e-12);
}

// A lone plane face, a ribbon along an arc of radius 50 (140 degrees) only 0.15 wide;
// each coedge on an edge of its own (as a file's shared edges) unless `free_coedges`.
constexpr double kRibbonR = 50, kRibbonW = 0.15, kRibbonSweep = 140 * M_PI / 180;
geom::Model ribbon(bool free_coedges) {
    geom::Face face = test::ribbon_face(kRibbonR, kRibbonW, kRibbonSweep);
    geom::Model model;
    for (geom::Coedge& coedge : face.loops[0].coedges) {
        if (free_coedges) break;
        coedge.edge = static_cast<int>(model.edges.size());
        model.edges.push_back({});
    }
    model.faces.push_back(face);
    return model;
}

TessellationResult mesh_ribbon(const geom::Model& model, double T) {
    TessellationOptions options;
    options.tolerance = T;
    options.threads = 1;
    return tessellate_model(model, options);
}

// At T = 2 the ribbon's two sides lie within the join's reach (0.1 T) of each other
// across the face (bug25837_S.igs at 0.01 of its diagonal). The join must not split
// one side's open edges at the other side's points: that folded triangles back over
// the ribbon (23 there, area 1.018x; here 36, area 1.77x). Every triangle faces +z,
// and the area is the ribbon's less what the chords cut off (each within T / 2).
TEST(TessellateModelWeld, RibbonThinnerThanTheJoinsReachDoesNotFold) {
    const double T = 2;
    const TessellationResult r = mesh_ribbon(ribbon(false), T);
    ASSERT_TRUE(r.failed_faces.empty()) << r.failed_faces[0].reason;
    int backward = 0;
    for (const auto& t : r.mesh.triangles)
        backward += (r.mesh.positions[t[1]] - r.mesh.positions[t[0]]).cross(r.mesh.positions[t[2]] - r.mesh.positions[t[0]]).z() < 0;
    EXPECT_EQ(backward, 0);
    const double R = kRibbonR, w = kRibbonW, exact = 0.5 * kRibbonSweep * ((R + w) * (R + w) - R * R);
    EXPECT_LE(mesh::surface_area(r.mesh), exact * (1 + 1e-9));
    EXPECT_GE(mesh::surface_area(r.mesh), exact - 0.5 * T * kRibbonSweep * (2 * R + w));
}

// The same ribbon with free coedges (faces-mode IGES): its two sides are different
// curves, not a seam, though within the sewing's reach (0.2 T). Sewn into one
// polyline they collapsed the face to 2 triangles: the arc 88 (44 T) from the mesh,
// area 0.12x, and the face passed its own check (a ribbon narrower than its lobe test
// looks across). Unsewn, the mesh is within T of the surface both ways (measured
// independently).
TEST(TessellateModelWeld, RibbonsTwoSidesAreNotSewnIntoOne) {
    const double T = 2;
    const geom::Model model = ribbon(true);
    const TessellationResult r = mesh_ribbon(model, T);
    ASSERT_TRUE(r.failed_faces.empty()) << r.failed_faces[0].reason;
    const DeviationReport d = measure_deviation(model, r.mesh);
    EXPECT_LE(d.mesh_to_surface.max, T);
    EXPECT_LE(d.surface_to_mesh.max, T);
    EXPECT_GT(d.area_ratio, 0.9);
    EXPECT_LE(d.area_ratio, 1.0 + 1e-9);
}

TEST(TessellateModelWeld, ThreadCountDoesNotChangeTheMesh) {
    const geom::Model model = cube();
    TessellationOptions options;
    options.tolerance = 1e-4;
    options.threads = 1;
    const TessellationResult one = tessellate_model(model, options);
    options.threads = 2;
    const TessellationResult two = tessellate_model(model, options);
    EXPECT_EQ(one.mesh.positions, two.mesh.positions);
    EXPECT_EQ(one.mesh.uvs, two.mesh.uvs);
    EXPECT_EQ(one.mesh.triangles, two.mesh.triangles);
    EXPECT_EQ(one.mesh.face_ids, two.mesh.face_ids);
}

// Two faces of a plate of thickness 1 and a side face between them along y = 0: a
// snap at a tolerance of 2 joins nothing that shares a triangle, so the side face
// keeps its area.
TEST(SnapBoundaryVertices, NeverCollapsesATriangleOrMovesBeyondTheTolerance) {
    mesh::Mesh m;
    m.positions = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0},       // bottom face
                   {0, 0, 1}, {10, 0, 1}, {0, 10, 1},       // top face
                   {0, 0, 0}, {10, 0, 0}, {10, 0, 1}, {0, 0, 1},  // side face
                   {10.5, 0, 0}};                           // a loose vertex near the bottom
    m.triangles = {{0, 2, 1}, {3, 4, 5}, {6, 7, 8}, {6, 8, 9}, {1, 10, 2}};
    m.face_ids = {0, 1, 2, 2, 3};
    const mesh::Mesh before = m;
    snap_boundary_vertices(m, 2.0);
    for (std::size_t v = 0; v < m.positions.size(); ++v)
        EXPECT_LE((m.positions[v] - before.positions[v]).norm(), 2.0);
    const auto tris = position_triangles(m, position_groups(m));
    for (const auto& t : tris) EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[2] != t[0]);
    // The side face holds the plate's edge at (0,0) and (10,0) open: its corners stay apart.
    EXPECT_NE(m.positions[0], m.positions[3]);
    EXPECT_NE(m.positions[1], m.positions[4]);
    EXPECT_GT(mesh::surface_area(m), 0.0);
}

// Default options with the tolerance kRelativeTolerance of the model's diagonal.
TessellationOptions at_relative_tolerance(const geom::Model& model) {
    TessellationOptions options;
    options.tolerance = kRelativeTolerance * model_diagonal(model);
    return options;
}

TEST(TessellateModelWeld, ThinPlateKeepsEveryFace) {
    TRIMKIT_CAD_SAMPLE(path, "iges/bug33327.igs");
    const geom::Model model = io::read_model(path);
    const TessellationOptions options = at_relative_tolerance(model);
    const TessellationResult r = tessellate_model(model, options);
    EXPECT_TRUE(r.failed_faces.empty());
    const std::set<std::int32_t> with_triangles(r.mesh.face_ids.begin(), r.mesh.face_ids.end());
    EXPECT_EQ(with_triangles.size(), model.faces.size());
    EXPECT_EQ(r.faces_meshed, static_cast<int>(model.faces.size()));
    EXPECT_EQ(r.open_edges, 0u);
}

// Open edges of the mesh as written (float positions), vertices joined by exact
// position through an ordered map.
std::size_t open_edges_by_float_position(const mesh::Mesh& m) {
    std::map<std::tuple<float, float, float>, std::int32_t> id;
    mesh::Mesh topology;
    for (const auto& p : m.positions) {
        const auto key = std::make_tuple(float(p.x()), float(p.y()), float(p.z()));
        if (!id.count(key)) {
            id.emplace(key, static_cast<std::int32_t>(topology.positions.size()));
            topology.positions.push_back(p);
        }
    }
    for (const auto& t : m.triangles) {
        std::array<std::int32_t, 3> u{};
        for (int k = 0; k < 3; ++k)
            u[k] = id.at(std::make_tuple(float(m.positions[t[k]].x()), float(m.positions[t[k]].y()),
                                         float(m.positions[t[k]].z())));
        topology.triangles.push_back(u);
    }
    return mesh::count_open_edges(topology);
}

// Issue 3 watertightness: a B-rep solid whose shared edges were mapped onto the
// second face's pcurve out of order (occ22470), a cone whose own seam vertices stay
// apart (OCC8842_cone_CATIA), grid crossings next to trim vertices that leave
// T-junctions inside the snap distance (occ22470, OCC17026-1), a boundary vertex
// just off the neighbour's chord under a sliver, so the chord is used three times
// (hammer face 5).
class ClosedAfterWeld : public ::testing::TestWithParam<const char*> {};

TEST_P(ClosedAfterWeld, NoOpenEdges) {
    TRIMKIT_CAD_SAMPLE(path, std::string("iges/") + GetParam());
    const geom::Model model = io::read_model(path);
    const TessellationOptions options = at_relative_tolerance(model);
    const TessellationResult r = tessellate_model(model, options);
    EXPECT_TRUE(r.failed_faces.empty());
    EXPECT_EQ(open_edges_by_float_position(r.mesh), 0u);
    // The reported count is the written mesh's (occ22470 once reported 6 on a closed
    // mesh: float rounding of the position keys was miscompiled).
    EXPECT_EQ(r.open_edges, 0u);
}

INSTANTIATE_TEST_SUITE_P(Issue3, ClosedAfterWeld,
                         ::testing::Values("occ22470.igs", "OCC8842_cone_CATIA.igs", "OCC17026-1.igs", "hammer.iges"));

// Two loose unit squares (no edges) side by side, the second `gap` above the first:
// z = 0 on [0,1]x[0,1] and z = gap on [1,2]x[0,1], each bounded by its natural loop.
geom::Model loose_squares(double gap) {
    geom::Model model;
    for (int k = 0; k < 2; ++k) {
        const double x0 = k, z = k * gap;
        geom::Face face;
        face.surface = geom::NurbsSurface(1, 1, {0, 0, 1, 1}, {0, 0, 1, 1}, 2, 2,
                                          {{x0, 0, z}, {x0, 1, z}, {x0 + 1, 0, z}, {x0 + 1, 1, z}});
        face.loops.push_back(geom::natural_boundary_loop(face.surface));
        model.faces.push_back(face);
    }
    return model;
}

// Largest distance of a face's mesh vertices from its plane z = face * gap.
double largest_vertex_move(const mesh::Mesh& m, double gap) {
    double largest = 0.0;
    for (std::size_t t = 0; t < m.triangles.size(); ++t)
        for (std::int32_t v : m.triangles[t])
            largest = std::max(largest, std::abs(m.positions[v].z() - m.face_ids[t] * gap));
    return largest;
}

// Joining faces moves their points by at most 0.1 T, and the faces are meshed to
// 0.9 T, so the joined mesh stays within T: a gap of 0.05 T is closed, one of 0.5 T
// (which a snap within T used to close, moving vertices 0.5 T off their faces on
// top of meshes that spent T: hammer.iges 1.29 T) is left open.
TEST(TessellateModelWeld, JoinMovesPointsByATenthOfTheToleranceAtMost) {
    TessellationOptions options;
    options.tolerance = 0.1;
    options.threads = 1;
    const TessellationResult closed = tessellate_model(loose_squares(0.05 * options.tolerance), options);
    const TessellationResult open = tessellate_model(loose_squares(0.5 * options.tolerance), options);
    ASSERT_EQ(closed.faces_meshed, 2);
    ASSERT_EQ(open.faces_meshed, 2);
    // The squares' outer boundary has at least 6 sides; the middle one at least 2.
    EXPECT_LT(closed.open_edges, open.open_edges);
    EXPECT_GT(largest_vertex_move(closed.mesh, 0.05 * options.tolerance), 0.0);
    EXPECT_LE(largest_vertex_move(closed.mesh, 0.05 * options.tolerance), 0.05 * options.tolerance + 1e-15);
    EXPECT_EQ(largest_vertex_move(open.mesh, 0.5 * options.tolerance), 0.0);
}

// hammer.iges (loose trimmed surfaces) at coarse tolerances, where the faces' own
// trim polylines lie far apart: every point within T of its face both ways, as
// `trimkit check` measures (1.57 T at 0.064 and 1.29 T at 0.016 with the snap within T).
class CoarseLooseModel : public ::testing::TestWithParam<double> {};

TEST_P(CoarseLooseModel, StaysWithinTheTolerance) {
    TRIMKIT_CAD_SAMPLE(path, "iges/hammer.iges");
    const geom::Model model = io::read_model(path);
    TessellationOptions options;
    options.tolerance = GetParam() * model_diagonal(model);
    const TessellationResult r = tessellate_model(model, options);
    EXPECT_TRUE(r.failed_faces.empty());
    const DeviationReport d = measure_deviation(model, r.mesh);
    EXPECT_LE(d.mesh_to_surface.max, options.tolerance);
    EXPECT_LE(d.surface_to_mesh.max, options.tolerance);
}

INSTANTIATE_TEST_SUITE_P(Hammer, CoarseLooseModel, ::testing::Values(0.064, 0.016));

// bug33327.igs places one definition 4 times: a relative tolerance is a fraction of
// the whole assembly, as the command line (which flattens) sees it.
TEST(ModelDiagonal, SpansEveryInstance) {
    TRIMKIT_CAD_SAMPLE(path, "iges/bug33327.igs");
    const geom::Model model = io::read_model(path);
    ASSERT_FALSE(model.instances.empty());
    const double placed = model_diagonal(geom::flatten_instances(model));
    EXPECT_DOUBLE_EQ(model_diagonal(model), placed);
    EXPECT_GT(placed, 1.5 * model_diagonal(geom::select_faces(model, model.bodies[0].faces)));
}

class DeviationWithinTolerance : public ::testing::TestWithParam<const char*> {};

TEST_P(DeviationWithinTolerance, BothDirections) {
    TRIMKIT_CAD_SAMPLE(path, std::string("iges/") + GetParam());
    const geom::Model model = io::read_model(path);
    const TessellationOptions options = at_relative_tolerance(model);
    const TessellationResult r = tessellate_model(model, options);
    EXPECT_TRUE(r.failed_faces.empty());
    const DeviationReport d = measure_deviation(model, r.mesh);
    EXPECT_LE(d.mesh_to_surface.max, options.tolerance) << "worst on face " << d.mesh_to_surface.worst.face;
    EXPECT_LE(d.surface_to_mesh.max, options.tolerance) << "worst on face " << d.surface_to_mesh.worst.face;
    EXPECT_NEAR(d.area_ratio, 1.0, kAreaRatioBand);
}

// Cylinders and a cone with a seam (the projection was clamped at the seam), closed
// rational tubes with C0 creases (Newton stalled at a crease), a file whose welded
// vertices carried another face's uv (BIGES), a thin plate.
INSTANTIATE_TEST_SUITE_P(Issue3, DeviationWithinTolerance,
                         ::testing::Values("OCC8842_cylinder_Ideas.igs", "OCC8842_cylinder_CATIA.igs",
                                           "OCC8842_cone_Ideas.igs", "OCC17026-1.igs", "BIGES.igs",
                                           "bug33327.igs", "occ22470.igs", "OCC8842_cone_CATIA.igs"));

}  // namespace
}  // namespace trimkit::tess
