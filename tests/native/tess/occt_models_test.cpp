// STEP and .brep readers on models built in the test with Open CASCADE (occt_models.h),
// read and meshed by trimkit and measured against areas and placements derived here:
// a plate with three holes (STEP), a cylinder face across its seam, damaged p-curves
// healed by ShapeFix, an assembly with one part placed twice, and solids read by
// trimkit's own STEP reader, with hand-written cylinder faces whose edges carry
// PCURVEs, and assemblies (placed, nested, in other units, cyclic, exploding) read by
// it as by OCCT's. Only with OCCT (the models are made with it).
#include <gtest/gtest.h>

#if TRIMKIT_HAVE_OCCT_MODELS
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>

#include "geom/error.h"
#include "geom/flatten_instances.h"
#include "io/occt_models.h"
#include "io/read_brep.h"
#include "io/read_model.h"
#include "io/read_step.h"
#include "tess/collapsed_side.h"
#include "tess/tessellate_model.h"
#include "step_text.h"
#include "test_support.h"

namespace trimkit {
namespace {

constexpr double kPi = 3.14159265358979323846;
using test::temp_path;

// Area of the triangles of `mesh` with face id `face` (-1: all).
double mesh_area(const mesh::Mesh& mesh, int face = -1) {
    double area = 0;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (face >= 0 && mesh.face_ids[t] != face) continue;
        const auto& tri = mesh.triangles[t];
        area += 0.5 * (mesh.positions[tri[1]] - mesh.positions[tri[0]])
                          .cross(mesh.positions[tri[2]] - mesh.positions[tri[0]])
                          .norm();
    }
    return area;
}

tess::TessellationResult mesh_at(const geom::Model& model, double tolerance) {
    tess::TessellationOptions options;
    options.tolerance = tolerance;
    options.threads = 1;
    return tess::tessellate_model(model, options);
}

#define REQUIRE_OCCT() \
    if (!io::step_supported()) GTEST_SKIP() << "trimkit built without Open CASCADE"

// A polygon inscribed in a circle within chord error T loses at most 2πr·T of its area
// (each chord's segment is thinner than T): the bound of every curved boundary here.
double curved_boundary_bound(double length, double T) { return length * T; }

TEST(OcctModels, PlateWithThreeHolesFromStepKeepsItsHoles) {
    REQUIRE_OCCT();
    const double L = 100, W = 60, H = 10, r = 8, T = 0.01;
    const std::string path = temp_path("plate3.step");
    test::write_plate_with_holes_step(path, L, W, H, {{20, 30}, {50, 30}, {80, 30}}, r);
    const geom::Model model = io::read_model(path);
    ASSERT_EQ(model.bodies.size(), 1u);
    EXPECT_TRUE(model.bodies[0].closed);
    int holed_planes = 0, cylinders = 0;
    for (const geom::Face& f : model.faces) {
        if (f.surface_kind == "plane" && f.loops.size() == 4) ++holed_planes;
        if (f.surface_kind == "cylinder") ++cylinders;
    }
    EXPECT_EQ(holed_planes, 2);  // top and bottom, each with three holes
    EXPECT_GE(cylinders, 3);
    const tess::TessellationResult result = mesh_at(model, T);
    EXPECT_TRUE(result.failed_faces.empty());
    EXPECT_EQ(result.open_edges, 0u);
    const double hole_length = 3 * 2 * kPi * r;
    for (size_t f = 0; f < model.faces.size(); ++f) {
        if (model.faces[f].loops.size() != 4) continue;
        const double exact = L * W - 3 * kPi * r * r;
        EXPECT_NEAR(mesh_area(result.mesh, static_cast<int>(f)), exact, curved_boundary_bound(hole_length, T))
            << "face " << f;
    }
    const double exact_total = 2 * (L * W - 3 * kPi * r * r) + 2 * (L + W) * H + 3 * 2 * kPi * r * H;
    EXPECT_NEAR(mesh_area(result.mesh), exact_total, curved_boundary_bound(2 * hole_length, T) + 3 * 2 * kPi * r * H * T / r);
    std::filesystem::remove(path);
}

// Signed area in (u,v) of a loop, its coedges sampled (shoelace).
double loop_signed_area(const geom::Loop& loop) {
    constexpr int kSamples = 64;
    double area = 0;
    for (const geom::Coedge& c : loop.coedges) {
        const auto [t0, t1] = c.curve.domain();
        for (int k = 0; k < kSamples; ++k) {
            const Eigen::Vector2d a = c.curve.evaluate(t0 + (t1 - t0) * k / kSamples);
            const Eigen::Vector2d b = c.curve.evaluate(t0 + (t1 - t0) * (k + 1) / kSamples);
            area += 0.5 * (a.x() * b.y() - b.x() * a.y());
        }
    }
    return area;
}

// face.h: the outer loop runs counter-clockwise in (u,v) when the face is not
// reversed and clockwise when it is, holes the other way; the STEP reader mirrors
// the loops of OCCT's reversed faces (a closed solid has both kinds), so meshing
// reorients none (it warned on every reversed face of bm2_ec_exhaust-A and bottle).
// Part 21 allows comments wherever blanks are, before the first token too; OCCT's
// parser skips them. The header check did not: "not a STEP file", as for a byte order mark.
TEST(OcctModels, StepCommentOrByteOrderMarkBeforeTheIsoLineIsRead) {
    REQUIRE_OCCT();
    const std::string plain = temp_path("plain.stp"), commented = temp_path("commented.stp");
    test::write_plate_with_holes_step(plain, 10, 8, 2, {{5, 4}}, 1);
    {
        std::ifstream in(plain);
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::ofstream out(commented);
        out << "/* written by a tool that signs its files */\n\n" << text;
    }
    const geom::Model a = io::read_model(plain), b = io::read_model(commented);
    EXPECT_EQ(a.faces.size(), 7u);  // the box's 6 sides and the hole's cylinder
    EXPECT_EQ(b.faces.size(), a.faces.size());
    // A UTF-8 byte order mark (a text editor's save) stops OCCT's parser: the own
    // reader takes the file, with a warning.
    {
        std::ifstream in(plain);
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::ofstream out(commented);
        out << "\xEF\xBB\xBF" << text;
    }
    const geom::Model c = io::read_model(commented);
    EXPECT_EQ(c.faces.size(), a.faces.size());
    ASSERT_FALSE(c.warnings.empty());
    EXPECT_NE(c.warnings[0].find("byte order mark"), std::string::npos) << c.warnings[0];
    std::filesystem::remove(plain);
    std::filesystem::remove(commented);
}

TEST(OcctModels, ReversedFacesLoopsFollowTheConvention) {
    REQUIRE_OCCT();
    const std::string path = temp_path("plate3_orient.step");
    test::write_plate_with_holes_step(path, 100, 60, 10, {{20, 30}, {50, 30}, {80, 30}}, 8);
    const geom::Model model = io::read_model(path);
    int reversed = 0, forward = 0;
    for (size_t f = 0; f < model.faces.size(); ++f) {
        const geom::Face& face = model.faces[f];
        (face.reversed ? reversed : forward) += 1;
        for (const geom::Loop& loop : face.loops) {
            const bool ccw = loop_signed_area(loop) > 0;
            EXPECT_EQ(ccw, loop.outer != face.reversed) << "face " << f << (loop.outer ? " outer" : " hole");
        }
    }
    EXPECT_GT(reversed, 0);
    EXPECT_GT(forward, 0);
    const tess::TessellationResult result = mesh_at(model, 0.01);
    for (const std::string& w : result.warnings) EXPECT_EQ(w.find("reoriented"), std::string::npos) << w;
    EXPECT_EQ(result.open_edges, 0u);
    std::filesystem::remove(path);
}

TEST(OcctModels, CylinderFaceAcrossTheSeamIsWhole) {
    REQUIRE_OCCT();
    const double R = 10, h = 5, T = 0.005;
    const std::string path = temp_path("seam.brep");
    test::write_cylinder_face_brep(path, R, h, -kPi / 2, kPi / 2);
    const geom::Model model = io::read_model(path);
    ASSERT_EQ(model.faces.size(), 1u);
    EXPECT_EQ(model.faces[0].surface_kind, "cylinder");
    const tess::TessellationResult result = mesh_at(model, T);
    ASSERT_TRUE(result.failed_faces.empty());
    // Half a turn: area π R h; the chords of a radius-R arc lose at most T/R of it.
    EXPECT_NEAR(mesh_area(result.mesh), kPi * R * h, kPi * R * h * T / R);
    for (const Eigen::Vector3d& p : result.mesh.positions) EXPECT_GE(p.x(), -1e-9);  // u in [-π/2, π/2]: x >= 0
    std::filesystem::remove(path);
}

// A thread's face (bottle.brep) winds round its cylinder more than once: its (u, v)
// trims span more than 2π, so one turn of the surface would cut it short.
TEST(OcctModels, HelicalStripWoundOneAndAHalfTurnsIsWhole) {
    REQUIRE_OCCT();
    const double R = 4, k = 0.5, w = 1, sweep = 3 * kPi, T = 0.002;
    const std::string path = temp_path("wound.brep");
    test::write_helical_strip_brep(path, R, k, w, sweep);
    const geom::Model model = io::read_model(path);
    ASSERT_EQ(model.faces.size(), 1u);
    const tess::TessellationResult result = mesh_at(model, T);
    ASSERT_TRUE(result.failed_faces.empty()) << result.failed_faces[0].reason;
    // dA = R du dv over a parallelogram of base `sweep` and height w: R sweep w.
    EXPECT_NEAR(mesh_area(result.mesh), R * sweep * w, R * sweep * w * T / R);
    std::filesystem::remove(path);
}

TEST(OcctModels, GappedAndMissingPcurvesAreHealedByShapeFix) {
    REQUIRE_OCCT();
    const double R = 10, h = 4, T = 0.005;
    for (double gap : {0.2, 0.0}) {
        const std::string path = temp_path("damaged.brep");
        test::write_damaged_cylinder_face_brep(path, R, h, gap);
        const geom::Model model = io::read_model(path);
        ASSERT_EQ(model.faces.size(), 1u) << "gap " << gap;
        bool healed = false;
        for (const std::string& w : model.faces[0].warnings) healed = healed || w.find("ShapeFix") != std::string::npos;
        for (const std::string& w : model.warnings) healed = healed || w.find("ShapeFix") != std::string::npos;
        EXPECT_TRUE(healed) << "gap " << gap;
        const tess::TessellationResult result = mesh_at(model, T);
        ASSERT_TRUE(result.failed_faces.empty()) << result.failed_faces[0].reason;
        EXPECT_NEAR(mesh_area(result.mesh), R * kPi / 2 * h, R * kPi / 2 * h * T / R) << "gap " << gap;
        std::filesystem::remove(path);
    }
}

// A p-curve that misses its neighbours by less than the vertices' tolerance (the
// file's promise that the ends meet; ul_to252.step's lead profiles, coordinates
// written to 3 decimals: 5.7e-4 apart under tolerances of 3.9e-4) is a closed joint,
// as OCCT takes it, however large against the face: the face was skipped at a
// relative gap of 1e-3 / 4 = 2.5e-4 (limit 1e-4).
TEST(OcctModels, PcurveGapWithinTheVertexToleranceKeepsItsFace) {
    REQUIRE_OCCT();
    const double R = 10, h = 4, T = 0.005, gap = 3e-3;
    const std::string path = temp_path("gap_within_tolerance.brep");
    test::write_damaged_cylinder_face_brep(path, R, h, gap, 2 * gap);
    const geom::Model model = io::read_model(path);
    ASSERT_EQ(model.faces.size(), 1u) << (model.warnings.empty() ? "" : model.warnings[0]);
    const tess::TessellationResult result = mesh_at(model, T);
    ASSERT_TRUE(result.failed_faces.empty()) << result.failed_faces[0].reason;
    // The bottom's p-curve runs gap above z = 0: the face is that much shorter.
    EXPECT_NEAR(mesh_area(result.mesh), R * kPi / 2 * (h - gap), R * kPi / 2 * h * T / R);
    std::filesystem::remove(path);
}

TEST(OcctModels, BsplineFaceTrimmedPastItsDomainKeepsTheWholeTrim) {
    REQUIRE_OCCT();
    const double L = 10, m = 0.05, T = 0.001;
    const std::string path = temp_path("past_domain.brep");
    test::write_bspline_face_past_domain_brep(path, L, m);
    const geom::Model model = io::read_model(path);
    ASSERT_EQ(model.faces.size(), 1u);
    const tess::TessellationResult result = mesh_at(model, T);
    ASSERT_TRUE(result.failed_faces.empty()) << result.failed_faces[0].reason;
    // The square of side L (1 + 2m), straight trims on a plane: exact up to rounding.
    EXPECT_NEAR(mesh_area(result.mesh), std::pow(L * (1 + 2 * m), 2), 1e-9 * L * L);
    std::filesystem::remove(path);
}

// A corner whose p-curves miss each other by 0.5 % of the domain in (u,v) but by
// 2.5e-5 of the face in 3D, where the surface hardly moves along u (Bottom.brep among
// OCCT's samples: one face of 323 skipped as "not closed after healing (relative gap
// 0.0006)" while its gap in 3D was 0.001 on a face 19 across). Kept and meshed whole:
// the bridge runs along v = 0, which is the square's bottom edge; the corner vertex
// lies at (0, 0, 0) or at the bottom edge's start (L gap^2, 0, 0), so the mesh may
// miss the sliver between them and the left side, of area L x L gap^2 / 2.
TEST(OcctModels, CornerOpenInUvButClosedIn3dKeepsItsFace) {
    REQUIRE_OCCT();
    const double L = 10, gap = 0.005;
    const std::string path = temp_path("slow_corner.brep");
    test::write_slow_corner_face_brep(path, L, gap);
    const geom::Model model = io::read_model(path);
    for (const std::string& w : model.warnings) ADD_FAILURE() << w;
    ASSERT_EQ(model.faces.size(), 1u);
    const tess::TessellationResult result = mesh_at(model, 0.01);
    ASSERT_TRUE(result.failed_faces.empty()) << result.failed_faces[0].reason;
    EXPECT_LE(mesh_area(result.mesh), L * L * (1 + 1e-12));
    EXPECT_GE(mesh_area(result.mesh), L * L - L * L * gap * gap / 2 - 1e-12 * L * L);
    std::filesystem::remove(path);
}

// A dx x dy x dz box placed twice (write_box_assembly_step): at t1, and turned 90°
// about z, then moved by t2.
struct BoxPair {
    double dx = 10, dy = 4, dz = 2;
    Eigen::Vector3d t1{100, 0, 0}, t2{0, 50, 7};

    void write(const std::string& path) const { test::write_box_assembly_step(path, dx, dy, dz, t1, t2); }

    // The two copies' boxes where the placements put them.
    void expect_boxes(const Eigen::AlignedBox3d& first, const Eigen::AlignedBox3d& second) const {
        EXPECT_TRUE(first.min().isApprox(t1, 1e-9));
        EXPECT_TRUE(first.max().isApprox(t1 + Eigen::Vector3d(dx, dy, dz), 1e-9));
        EXPECT_TRUE(second.min().isApprox(t2 + Eigen::Vector3d(-dy, 0, 0), 1e-9));
        EXPECT_TRUE(second.max().isApprox(t2 + Eigen::Vector3d(0, dx, dz), 1e-9));
    }
};

TEST(OcctModels, AssemblyPartPlacedTwiceIsOneBodyTwoInstances) {
    REQUIRE_OCCT();
    const BoxPair pair;
    const std::string path = temp_path("pair.step");
    pair.write(path);
    const geom::Model model = io::read_model(path);
    ASSERT_EQ(model.bodies.size(), 1u);
    EXPECT_EQ(model.faces.size(), 6u);
    ASSERT_EQ(model.instances.size(), 2u);
    EXPECT_EQ(model.bodies[0].name, "block");
    // The first copy only moves; the second turns by 90° about z, then moves.
    Eigen::Affine3d second = Eigen::Translation3d(pair.t2) * Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitZ());
    EXPECT_TRUE(
        model.instances[0].transform.matrix().isApprox(Eigen::Affine3d(Eigen::Translation3d(pair.t1)).matrix(), 1e-9));
    EXPECT_TRUE(model.instances[1].transform.matrix().isApprox(second.matrix(), 1e-9));
    ASSERT_EQ(model.instances[0].path.size(), 1u);
    EXPECT_EQ(model.instances[0].path[0], "pair");
    // Flattened: the boxes' corners where the placements put them.
    const geom::Model flat = geom::flatten_instances(model);
    const tess::TessellationResult result = mesh_at(flat, 0.01);
    EXPECT_EQ(result.mesh.triangle_count(), 2u * 12u);
    Eigen::AlignedBox3d first, other;
    for (size_t t = 0; t < result.mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            (result.mesh.face_ids[t] < 6 ? first : other).extend(result.mesh.positions[result.mesh.triangles[t][k]]);
    pair.expect_boxes(first, other);
    EXPECT_NEAR(mesh_area(result.mesh), 2 * 2 * (pair.dx * pair.dy + pair.dy * pair.dz + pair.dx * pair.dz), 1e-9);
    std::filesystem::remove(path);
}

// A model read and meshed at T: every face meshed, none failed, no open edge, and the
// mesh's area within 0.2 % (issue 9's acceptance) of OCCT's BRepGProp area.
void expect_whole(const geom::Model& model, double T, double occt_area, const std::string& what) {
    const tess::TessellationResult result = mesh_at(model, T);
    for (const tess::FailedFace& f : result.failed_faces) ADD_FAILURE() << what << ": " << f.reason;
    EXPECT_EQ(result.faces_meshed, static_cast<int>(model.faces.size())) << what;
    EXPECT_EQ(result.open_edges, 0u) << what;
    EXPECT_NEAR(mesh_area(result.mesh) / occt_area, 1.0, 2e-3) << what;
}

// The area of triangles standing across the surface: a vertex's exact normal at more
// than 60 degrees from the triangle's (a mesh within T of a surface of curvature
// radius r >> T tilts its triangles by far less; tube radius 12 at T = 1.5: < 30).
double standing_area(const mesh::Mesh& m) {
    double area = 0.0;
    for (const auto& t : m.triangles) {
        const Eigen::Vector3d n = (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]);
        if (!(n.norm() > 0.0)) continue;
        bool standing = false;
        for (int k = 0; k < 3; ++k) standing = standing || std::abs(n.normalized().dot(m.normals[t[k]])) < 0.5;
        if (standing) area += 0.5 * n.norm();
    }
    return area;
}

bool any_warning(const geom::Model& model, const std::string& part) {
    for (const geom::Face& f : model.faces)
        for (const std::string& w : f.warnings)
            if (w.find(part) != std::string::npos) return true;
    return false;
}

// OCCT's IGES B-rep writer flags the hole at u = pi as the lateral face's outer loop;
// the loop that runs round the other hole (on the seam) and along both end circles
// encloses it. Trusting the flag kept 3 % of the face.
// A shell whose faces have edges of their own (Spatial's STEP surface models; OCCT's
// transfer splits it into a shell per face) is sewn by OCCT on reading: one closed
// body with shared edges, meshed closed, its area OCCT's; a warning says it was sewn.
TEST(OcctModels, ShellOfLooseFacesIsSewnIntoOneClosedBody) {
    REQUIRE_OCCT();
    const std::string solid_path = temp_path("rounded_solid.stp");
    test::write_rounded_box(solid_path, 50, 40, 30, 5);
    const std::size_t solid_edges = io::read_model(solid_path).edges.size();
    std::filesystem::remove(solid_path);
    for (const char* name : {"loose_faces.stp", "loose_faces.brep"}) {
        const std::string path = temp_path(name);
        const double area = test::write_loose_face_rounded_box(path);
        const geom::Model model = io::read_model(path);
        EXPECT_EQ(model.faces.size(), 26u) << name;  // 6 sides, 12 fillets, 8 corners
        ASSERT_EQ(model.bodies.size(), 1u) << name;
        EXPECT_TRUE(model.bodies[0].closed) << name;
        EXPECT_EQ(model.edges.size(), solid_edges) << name;  // the solid's own edges, each shared
        EXPECT_TRUE(std::any_of(model.warnings.begin(), model.warnings.end(), [](const std::string& w) {
            return w.find("sewn by BRepBuilderAPI_Sewing") != std::string::npos;
        })) << name;
        expect_whole(model, 0.01, area, name);
        std::filesystem::remove(path);
    }
}

TEST(OcctModels, IgesBrepCylinderWhoseOuterFlagNamesAHoleKeepsItsLateralFace) {
    REQUIRE_OCCT();
    const std::string path = temp_path("cross_hole.igs");
    const double area = test::write_cylinder_cross_hole_iges(path, 20, 60, 6);
    const geom::Model model = io::read_model(path);
    EXPECT_EQ(model.faces.size(), 4u);
    EXPECT_TRUE(any_warning(model, "encloses loop 1; taken as the outer loop"));
    expect_whole(model, 0.05, area, "cylinder with a cross hole");
    std::filesystem::remove(path);
}

// The sphere face's outer loop runs from the pole down its seam edge and round the
// equator: the seam must be used on the side away from its partner and not be
// unwrapped across the pole, or the loop lands a period from the box cut's loop at
// u in [0.2, 1.4] and the cut is outside the face (22 % of the area was kept).
TEST(OcctModels, IgesBrepSphereLoopsAPeriodApartArePlacedTogether) {
    REQUIRE_OCCT();
    const std::string path = temp_path("sphere_pole.igs");
    const double area = test::write_sphere_cut_near_pole_iges(path, 25, 5, 3, 4);
    const geom::Model model = io::read_model(path);
    EXPECT_EQ(model.faces.size(), 5u);
    expect_whole(model, 0.05, area, "sphere cut near its pole");
    std::filesystem::remove(path);
}

// A whole ball (OCCT's Axis_of_bearing.brep through its IGES writer: ten balls):
// the loop is the seam edge twice, both uses projected onto u = 0, and the seam
// sides were settled only after a coedge off the seam, which this loop lacks: the
// loop had no area and the face "no triangles".
TEST(OcctModels, IgesWholeBallWhoseLoopIsItsSeamTwiceIsMeshed) {
    REQUIRE_OCCT();
    for (const bool brep_mode : {true, false}) {
        const std::string path = temp_path(brep_mode ? "ball_brep.igs" : "ball_faces.igs");
        const double area = test::write_whole_ball_iges(path, 2, brep_mode);
        const geom::Model model = io::read_model(path);
        EXPECT_EQ(model.faces.size(), 1u) << path;
        expect_whole(model, 0.01, area, brep_mode ? "B-rep mode" : "faces mode");
        std::filesystem::remove(path);
    }
}

// The hole on the sphere's seam: its two half circles end on the seam, one from
// below 2pi and one from above 0, and the seam runs from each pole to the hole and
// back. In faces mode (no shared edges) both uses of a seam stretch took the same
// side, so the hole was covered (this test failed on faces mode). In B-rep mode the
// corpus's perforated ball (bench/RESULTS.md) showed the other half of the class:
// the projector gave the lower half circle a period off (u in [-0.13, 0]) and the
// seam took the wrong sides; this single hole does not start its loop there.
TEST(OcctModels, IgesSphereWithAHoleOnItsSeamKeepsTheHoleInBothModes) {
    REQUIRE_OCCT();
    for (const bool brep_mode : {true, false}) {
        const std::string path = temp_path(brep_mode ? "seam_hole_brep.igs" : "seam_hole_faces.igs");
        const double area = test::write_ball_hole_on_seam_iges(path, 30, 6, brep_mode);
        const geom::Model model = io::read_model(path);
        EXPECT_EQ(model.faces.size(), 3u) << path;  // sphere, cylinder, end disc
        expect_whole(model, 0.05, area, brep_mode ? "B-rep mode" : "faces mode");
        std::filesystem::remove(path);
    }
}

// The cone's apex is one side of its (u,v) domain. Cells on that side were
// triangulated in (u,v), where a fan from the side folds in 3D beside the hole
// (a backward triangle of area 11.8: area +0.24 %, within T both ways).
TEST(OcctModels, ConeApexCellsBesideAHoleDoNotFold) {
    REQUIRE_OCCT();
    const std::string path = temp_path("cone_apex.igs");
    const double area = test::write_cone_apex_hole_iges(path, 30, 50, 4, false);
    const geom::Model model = io::read_model(path);
    EXPECT_EQ(model.faces.size(), 3u);
    for (double T : {0.05, 0.1, 0.2}) expect_whole(model, T, area, "T = " + std::to_string(T));
    std::filesystem::remove(path);
}

// The fillets' loops run along the torus's knot line v = pi/2, a few 1e-10 either
// side of it after the trim approximation; the cells above lost their kept regions
// and the fillet faces failed ("trim loop lies 6.8 T from the mesh boundary").
TEST(OcctModels, FilletAlongAKnotLineKeepsItsCells) {
    REQUIRE_OCCT();
    const std::string path = temp_path("filleted_holes.igs");
    const double area = test::write_filleted_hole_block_iges(path);
    const geom::Model model = io::read_model(path);
    EXPECT_EQ(model.faces.size(), 12u);
    for (double T : {0.025, 0.09, 0.27}) expect_whole(model, T, area, "T = " + std::to_string(T));
    std::filesystem::remove(path);
}

// IGES faces mode writes a torus as a 120 surface of revolution of a 100 arc. The
// arc's parameter is its angle, the NURBS arc's only at its knots, and OCCT's writer
// keeps its circle's parameters (3pi/2..2pi) where the arc read by IGES 5.3's rule
// starts at atan2 = -pi/2: Top.brep's fillets through OCCT's IGES writer were
// "(u,v) box misses the surface's domain" (21 of 324 faces failed), and a loop
// across the arc's parameters was mapped with the angle taken for the NURBS's.
TEST(OcctModels, IgesRevolvedArcTrimsTakeTheArcsAnglesOnEitherTurn) {
    REQUIRE_OCCT();
    for (const auto& [a, b] : {std::pair{1.5 * M_PI, 2 * M_PI}, std::pair{-0.5 * M_PI, 0.0}, std::pair{0.3, 1.9}}) {
        const std::string path = temp_path("revolved_arc.igs");
        const double area = test::write_revolved_arc_hole_iges(path, a, b);
        const geom::Model model = io::read_model(path);
        ASSERT_EQ(model.faces.size(), 1u);
        for (double T : {0.02, 0.1}) {
            const std::string what = "arc " + std::to_string(a) + ".." + std::to_string(b) + ", T " + std::to_string(T);
            const tess::TessellationResult result = mesh_at(model, T);
            for (const tess::FailedFace& f : result.failed_faces) ADD_FAILURE() << what << ": " << f.reason;
            EXPECT_EQ(result.faces_meshed, 1) << what;
            EXPECT_NEAR(mesh_area(result.mesh) / area, 1.0, 2e-3) << what;
        }
        std::filesystem::remove(path);
    }
}

// The torus face's loop runs along v = 0 and 2pi, knot lines of the surface the reader
// extended past its seam, 1e-9 inside the grid's margin: a row of cells thinner than
// the margin held the trim, and its triangles, flat in (u,v), stood across the surface
// along the seam circles (area +0.44 % at 0.01 of the diagonal, within T both ways).
TEST(OcctModels, TorusTrimmedAlongExtendedKnotLinesHasNoStandingSlivers) {
    REQUIRE_OCCT();
    const std::string path = temp_path("torus_seams.igs");
    const double area = test::write_torus_hole_on_seams_iges(path);
    const geom::Model model = io::read_model(path);
    EXPECT_EQ(model.faces.size(), 3u);
    for (double T : {1.48862, 0.15}) expect_whole(model, T, area, "T = " + std::to_string(T));
    for (double T : {1.5, 0.6, 0.15})
        EXPECT_LT(standing_area(mesh_at(model, T).mesh), 5e-4 * area) << "T = " << T;  // was 8e-4 to 9e-3
    std::filesystem::remove(path);
}

// A 194 cone is sized by its boundary points plus a margin; the margin carried its
// range past the apex onto the other nappe, so the apex was an inner line of the
// domain and the face took 84 000 triangles at T = 0.01 (OCCT: 9 600 for the solid).
// Now the apex is the domain's side (collapsed_sides finds it) and the face is light.
TEST(OcctModels, IgesConeRangeStopsAtItsApex) {
    REQUIRE_OCCT();
    const std::string path = temp_path("cone_apex_brep.igs");
    const double area = test::write_cone_apex_hole_iges(path, 30, 50, 4, true);
    const geom::Model model = io::read_model(path);
    ASSERT_EQ(model.faces.size(), 3u);
    const geom::Face* cone = nullptr;
    for (const geom::Face& f : model.faces)
        if (f.surface_kind == "cone") cone = &f;
    ASSERT_NE(cone, nullptr);
    const tess::CollapsedSides sides = tess::collapsed_sides(cone->surface);
    EXPECT_EQ(std::count(sides.begin(), sides.end(), true), 1);
    expect_whole(model, 0.1, area, "T = 0.1");
    const tess::TessellationResult fine = mesh_at(model, 0.01);
    EXPECT_LT(fine.mesh.triangle_count(), 20000u);
    std::filesystem::remove(path);
}

// A ruled face needs no inner points, so a cell spans a whole ruling of the frustum;
// a triangle from the ruling's ends to a hole point just beside their (u,v) chord
// faced backwards in 3D (two of area 8.8 at T = 0.8: area +0.28 %, within T).
TEST(OcctModels, FrustumCellsAlongWholeRulingsDoNotFold) {
    REQUIRE_OCCT();
    const std::string path = temp_path("frustum.igs");
    const double area = test::write_frustum_hole_on_seam_iges(path);
    const geom::Model model = io::read_model(path);
    EXPECT_EQ(model.faces.size(), 4u);
    for (double T : {0.8124, 0.4, 0.08}) {
        expect_whole(model, T, area, "T = " + std::to_string(T));
        EXPECT_LT(standing_area(mesh_at(model, T).mesh), 5e-4 * area) << "T = " << T;
    }
    std::filesystem::remove(path);
}

// A prism over a periodic B-spline as .brep: OCCT converts the plane faces' computed
// p-curves over exactly one period into curves that do not close; the reader unrolls
// the period itself (it skipped both plane faces: "trim loops are not closed").
TEST(OcctModels, BrepPrismOverAPeriodicSplineKeepsItsPlaneFaces) {
    REQUIRE_OCCT();
    std::vector<Eigen::Vector2d> outline;
    for (int i = 0; i < 12; ++i) {
        const double a = 2 * kPi * i / 12, r = i % 2 == 0 ? 40 : 28;
        outline.emplace_back(r * std::cos(a), r * std::sin(a));
    }
    const std::string path = temp_path("spline_prism.brep");
    const double area = test::write_periodic_spline_prism_brep(path, outline, 20);
    const geom::Model model = io::read_model(path);
    ASSERT_EQ(model.faces.size(), 3u);
    int planes = 0;
    for (const geom::Face& f : model.faces) planes += f.surface_kind == "plane";
    EXPECT_EQ(planes, 2);
    expect_whole(model, 0.05, area, "prism over a periodic spline");
    std::filesystem::remove(path);
}

// ---- trimkit's own STEP reader (io/read_step_native.h) on the same kind of models,
// written by OCCT's STEP writer: its faces, shared edges and bodies, and the mesh of
// its model against BRepGProp's area and the model OCCT's reader gives.

io::ReadOptions own_reader() {
    io::ReadOptions options;
    options.step_reader = io::StepReader::kOwn;
    return options;
}

struct Solid {
    const char* name;
    std::function<double(const std::string&)> write;  // writes the STEP file, returns its area
};

// Each solid: own reader's faces as many as OCCT reader's, one closed body, every edge
// shared by two faces (no open edges in the mesh), no failed face, and the mesh's area
// within 0.2 % of BRepGProp's (the acceptance bar of issue 9).
class OwnStepReader : public ::testing::TestWithParam<Solid> {};

TEST_P(OwnStepReader, ReadsTheSolidAsOcctDoesAndMeshesItsArea) {
    if (!io::step_supported()) GTEST_SKIP() << "trimkit built without Open CASCADE";
    const Solid& solid = GetParam();
    const std::string path = temp_path("own_" + std::string(solid.name) + ".stp");
    const double area = solid.write(path);
    const geom::Model own = io::read_step(path, own_reader());
    const geom::Model occt = io::read_step(path);
    EXPECT_EQ(own.faces.size(), occt.faces.size());
    ASSERT_EQ(own.bodies.size(), 1u);
    EXPECT_TRUE(own.bodies[0].closed);
    EXPECT_EQ(own.units, "mm");
    const double T = 0.01;
    const tess::TessellationResult result = mesh_at(own, T);
    EXPECT_TRUE(result.failed_faces.empty()) << result.failed_faces.size() << " failed, first: "
                                             << (result.failed_faces.empty() ? "" : result.failed_faces[0].reason);
    EXPECT_EQ(result.open_edges, 0u);
    EXPECT_NEAR(mesh_area(result.mesh), area, 2e-3 * area);
}

INSTANTIATE_TEST_SUITE_P(
    Solids, OwnStepReader,
    ::testing::Values(
        Solid{"plate_with_holes",
              [](const std::string& p) {
                  test::write_plate_with_holes_step(p, 100, 60, 10, {{20, 30}, {50, 30}, {80, 30}}, 8);
                  return 2 * (100 * 60 - 3 * kPi * 64) + 2 * 10 * (100 + 60) + 3 * 2 * kPi * 8 * 10;
              }},
        Solid{"cylinder_cross_hole", [](const std::string& p) { return test::write_cylinder_cross_hole_iges(p, 20, 60, 6); }},
        Solid{"sphere_cut_near_pole",
              [](const std::string& p) { return test::write_sphere_cut_near_pole_iges(p, 25, 5, 3, 4); }},
        Solid{"ball_hole_on_seam", [](const std::string& p) { return test::write_ball_hole_on_seam_iges(p, 30, 6, true); }},
        Solid{"whole_ball", [](const std::string& p) { return test::write_whole_ball_iges(p, 25, true); }},
        // Its seam's two pieces have SEAM_CURVEs whose PCURVEs both map onto u = 2 pi: the
        // loop was a sliver along one side and the ball kept half its area until face_loops
        // settled the sides of the file's seam curves as of projected ones.
        Solid{"perforated_ball", [](const std::string& p) { return test::write_perforated_ball(p, 30, 3, 6); }},
        // Corner octants run down the sphere's seam to its pole and turn there: the seam
        // curve took the side the pole (any u) gave, the loop was closed along the equator
        // round the rest of the sphere and 88 edges of plate_with_holes.stp were open,
        // until the coedge after the pole decided the side.
        Solid{"rounded_box", [](const std::string& p) { return test::write_rounded_box(p, 50, 30, 20, 4); }},
        // Meridians a little off the seam: the coedges after the pole were placed from the
        // one leaving it, a period away, and the octant became the rest of the sphere
        // (unwrap_loop places them back from the loop's start).
        Solid{"sewn_rounded_box", [](const std::string& p) { return test::write_sewn_rounded_box(p); }},
        Solid{"cone_apex_hole", [](const std::string& p) { return test::write_cone_apex_hole_iges(p, 30, 50, 4, true); }},
        Solid{"filleted_hole_block", [](const std::string& p) { return test::write_filleted_hole_block_iges(p); }},
        Solid{"torus_hole_on_seams", [](const std::string& p) { return test::write_torus_hole_on_seams_iges(p); }},
        Solid{"frustum_hole_on_seam", [](const std::string& p) { return test::write_frustum_hole_on_seam_iges(p); }}),
    [](const ::testing::TestParamInfo<Solid>& info) { return std::string(info.param.name); });

// ---- The own reader's use of the file's PCURVEs (read_step_native.cpp): hand-written
// cylinder faces whose edges are SURFACE_CURVEs / SEAM_CURVEs with PCURVEs on the face's
// CYLINDRICAL_SURFACE (no units: millimetres and radians). A PCURVE taken leaves no
// "projected from model space" warning; a wrong one is checked against the 3D curve,
// projected instead (with a warning) and the face keeps its area.

using test::cylinder_entities;
using test::step_file;
using test::step_real;

// The 2D line #id through (u, v) along #vector, its DEFINITIONAL_REPRESENTATION #id+2
// and PCURVE #id+3 on the cylinder #5.
std::string cylinder_pcurve(int id, double u, double v, int vector) {
    const std::string n = std::to_string(id);
    return "#" + std::to_string(id + 1) + "=CARTESIAN_POINT('',(" + step_real(u) + "," + step_real(v) + "));\n#" +
           n + "=LINE('',#" + std::to_string(id + 1) + ",#" + std::to_string(vector) + ");\n#" +
           std::to_string(id + 2) + "=DEFINITIONAL_REPRESENTATION('',(#" + n + "),#99);\n#" +
           std::to_string(id + 3) + "=PCURVE('',#5,#" + std::to_string(id + 2) + ");\n";
}

// A quarter of the cylinder (angles 0 to π/2, heights 0 to h) bounded by two arcs and
// two rulings; the ruling at angle 0 has its PCURVE at angle `ruling_u` (0: right).
std::string quarter_cylinder_step(double r, double h, double ruling_u) {
    return step_file(
        cylinder_entities(r, h) + "#11=CARTESIAN_POINT('',(" + step_real(r) + ",0.,0.));\n" +
        "#12=CARTESIAN_POINT('',(0.," + step_real(r) + ",0.));\n#13=CARTESIAN_POINT('',(0.," + step_real(r) + "," +
        step_real(h) + "));\n#14=CARTESIAN_POINT('',(" + step_real(r) + ",0.," + step_real(h) + "));\n" +
        "#15=VERTEX_POINT('',#11);\n#16=VERTEX_POINT('',#12);\n#17=VERTEX_POINT('',#13);\n#18=VERTEX_POINT('',#14);\n"
        "#19=LINE('',#11,#10);\n#20=LINE('',#12,#10);\n" +
        cylinder_pcurve(100, 0, 0, 31) + cylinder_pcurve(110, 0, h, 31) + cylinder_pcurve(120, ruling_u, 0, 33) +
        cylinder_pcurve(130, 0.5 * kPi, 0, 33) +
        "#50=SURFACE_CURVE('',#8,(#103),.PCURVE_S1.);\n#51=SURFACE_CURVE('',#9,(#113),.PCURVE_S1.);\n"
        "#52=SURFACE_CURVE('',#19,(#123),.PCURVE_S1.);\n#53=SURFACE_CURVE('',#20,(#133),.PCURVE_S1.);\n"
        "#54=EDGE_CURVE('',#15,#16,#50,.T.);\n#55=EDGE_CURVE('',#18,#17,#51,.T.);\n"
        "#56=EDGE_CURVE('',#15,#18,#52,.T.);\n#57=EDGE_CURVE('',#16,#17,#53,.T.);\n"
        "#58=ORIENTED_EDGE('',*,*,#54,.T.);\n#59=ORIENTED_EDGE('',*,*,#57,.T.);\n"
        "#60=ORIENTED_EDGE('',*,*,#55,.F.);\n#61=ORIENTED_EDGE('',*,*,#56,.F.);\n"
        "#62=EDGE_LOOP('',(#58,#59,#60,#61));\n#63=FACE_OUTER_BOUND('',#62,.T.);\n"
        "#64=ADVANCED_FACE('',(#63),#5,.T.);\n");
}

// The whole band of the cylinder: its bottom and top circles (closed edges) and the
// seam ruling at angle 0, a SEAM_CURVE with PCURVEs u = 0 and u = 2π, used up and down.
std::string cylinder_band_step(double r, double h) {
    return step_file(
        cylinder_entities(r, h) + "#11=CARTESIAN_POINT('',(" + step_real(r) + ",0.,0.));\n" +
        "#14=CARTESIAN_POINT('',(" + step_real(r) + ",0.," + step_real(h) + "));\n" +
        "#15=VERTEX_POINT('',#11);\n#18=VERTEX_POINT('',#14);\n#19=LINE('',#11,#10);\n" +
        cylinder_pcurve(100, 0, 0, 31) + cylinder_pcurve(110, 0, h, 31) + cylinder_pcurve(120, 0, 0, 33) +
        cylinder_pcurve(130, 2 * kPi, 0, 33) +
        "#50=SURFACE_CURVE('',#8,(#103),.PCURVE_S1.);\n#51=SURFACE_CURVE('',#9,(#113),.PCURVE_S1.);\n"
        "#52=SEAM_CURVE('',#19,(#123,#133),.PCURVE_S1.);\n"
        "#54=EDGE_CURVE('',#15,#15,#50,.T.);\n#55=EDGE_CURVE('',#18,#18,#51,.T.);\n"
        "#56=EDGE_CURVE('',#15,#18,#52,.T.);\n"
        "#58=ORIENTED_EDGE('',*,*,#54,.T.);\n#59=ORIENTED_EDGE('',*,*,#56,.T.);\n"
        "#60=ORIENTED_EDGE('',*,*,#55,.F.);\n#61=ORIENTED_EDGE('',*,*,#56,.F.);\n"
        "#62=EDGE_LOOP('',(#58,#59,#60,#61));\n#63=FACE_OUTER_BOUND('',#62,.T.);\n"
        "#64=ADVANCED_FACE('',(#63),#5,.T.);\n");
}

// The warnings of the model's only face that contain `text`.
int warnings_with(const geom::Model& model, const std::string& text) {
    int n = 0;
    for (const std::string& w : model.faces.at(0).warnings) n += w.find(text) != std::string::npos;
    return n;
}

// Reads `text` with the own reader and meshes it within T = 1e-3; checks the one face's
// area against `area` of a cylinder patch of radius r with boundary length `perimeter`:
// a surface within T of the cylinder has an area within a factor 1 ± T/r of it (Steiner:
// the parallel surface at distance d has the factor 1 + d/r), its boundary within T
// of the exact one changes it by at most perimeter × T.
geom::Model read_own_and_check_area(const std::string& name, const std::string& text, double area, double r,
                                    double perimeter) {
    const std::string path = temp_path(name);
    {
        std::ofstream out(path);
        out << text;
    }
    const geom::Model model = io::read_step(path, own_reader());
    std::filesystem::remove(path);
    EXPECT_EQ(model.faces.size(), 1u);
    if (model.faces.size() != 1) return model;
    const double T = 1e-3;
    const tess::TessellationResult result = mesh_at(model, T);
    EXPECT_TRUE(result.failed_faces.empty());
    EXPECT_NEAR(mesh_area(result.mesh), area, area * T / r + curved_boundary_bound(perimeter, T));
    return model;
}

// A file OCCT parses but transfers nothing from (NIST's switcharm.step, 1995: an
// ADVANCED_BREP_REPRESENTATION and no product structure) is read by the own reader
// on the default path, with a warning that says so; the face is the quarter cylinder.
TEST(OwnStepReader, TakesTheFilesOcctTransfersNothingFrom) {
    REQUIRE_OCCT();
    const double r = 10, h = 20;
    std::string text = quarter_cylinder_step(r, h, 0);
    const std::size_t products = text.find("#9001="), end = text.find("ENDSEC;", products);
    ASSERT_NE(products, std::string::npos);
    text.replace(products, end - products, "#9013=ADVANCED_BREP_REPRESENTATION('',(#66),#99);\n");
    const std::string path = temp_path("no_products.stp");
    {
        std::ofstream out(path);
        out << text;
    }
    io::ReadOptions occt_only;
    occt_only.step_reader = io::StepReader::kOcct;
    const geom::Model model = io::read_step(path, occt_only);
    std::filesystem::remove(path);
    ASSERT_EQ(model.faces.size(), 1u);
    ASSERT_FALSE(model.warnings.empty());
    EXPECT_NE(model.warnings[0].find("Open CASCADE transfers no shape"), std::string::npos) << model.warnings[0];
    EXPECT_NE(model.warnings[0].find("own STEP reader"), std::string::npos) << model.warnings[0];
    const double T = 1e-3, area = r * 0.5 * kPi * h;
    const tess::TessellationResult result = mesh_at(model, T);
    EXPECT_TRUE(result.failed_faces.empty());
    EXPECT_NEAR(mesh_area(result.mesh), area, area * T / r + curved_boundary_bound(kPi * r + 2 * h, T));
}

TEST(OwnStepReader, TakesTheFilesPcurvesOnACylinderQuarter) {
    const double r = 10, h = 20;
    const geom::Model model = read_own_and_check_area("pc_quarter.stp", quarter_cylinder_step(r, h, 0), r * 0.5 * kPi * h,
                                                        r, kPi * r + 2 * h);
    if (model.faces.size() != 1) return;
    EXPECT_EQ(warnings_with(model, "projected"), 0);
    // The loop's corners in (u, v) are the PCURVEs' ends mapped: the surface there is at the vertices.
    const geom::Face& f = model.faces[0];
    ASSERT_EQ(f.loops.size(), 1u);
    ASSERT_EQ(f.loops[0].coedges.size(), 4u);
    for (const geom::Coedge& c : f.loops[0].coedges) {
        const Eigen::Vector2d uv = c.curve.evaluate(c.curve.domain().first);
        const Eigen::Vector3d x = f.surface.evaluate(uv.x(), uv.y());
        EXPECT_NEAR(std::hypot(x.x(), x.y()), r, 1e-9);
        EXPECT_TRUE(std::fabs(x.z()) < 1e-9 || std::fabs(x.z() - h) < 1e-9) << x.transpose();
        EXPECT_TRUE(std::fabs(x.x()) < 1e-9 || std::fabs(x.y()) < 1e-9) << x.transpose();
    }
}

TEST(OwnStepReader, AWrongPcurveIsProjectedInsteadAndTheAreaHolds) {
    const double r = 10, h = 20;
    // The ruling at angle 0 given a PCURVE at angle 0.5: 2 r sin(0.25) = 4.9 off the line.
    const geom::Model model = read_own_and_check_area("pc_wrong.stp", quarter_cylinder_step(r, h, 0.5),
                                                        r * 0.5 * kPi * h, r, kPi * r + 2 * h);
    if (model.faces.size() != 1) return;
    EXPECT_EQ(warnings_with(model, "parameter curve is off its model-space curve"), 1);
    EXPECT_EQ(warnings_with(model, "projected from model space"), 1);
}

// A seam's two PCURVEs may map onto one side of the domain: face_loops settles the
// sides (settle_seam_sides) as for projected seams, and the band is whole.
TEST(OwnStepReader, TakesBothPcurvesOfASeamOnACylinderBand) {
    const double r = 10, h = 20;
    const geom::Model model = read_own_and_check_area("pc_band.stp", cylinder_band_step(r, h), 2 * kPi * r * h, r,
                                                        4 * kPi * r);
    if (model.faces.size() != 1) return;
    EXPECT_EQ(warnings_with(model, "projected"), 0);
}

// ---- Assemblies read by trimkit's own reader (step_assembly.h) ----------------------

std::string read_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void write_text(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

// Each instance of `own` is one of `occt`'s: the same name, path and transform, and a
// body with as many faces; no instance of OCCT's is left over.
void expect_same_instances(const geom::Model& own, const geom::Model& occt, const std::string& what) {
    ASSERT_EQ(own.instances.size(), occt.instances.size()) << what;
    std::vector<bool> taken(occt.instances.size(), false);
    for (const geom::Instance& i : own.instances) {
        bool found = false;
        for (std::size_t k = 0; k < occt.instances.size() && !found; ++k) {
            const geom::Instance& o = occt.instances[k];
            if (taken[k] || o.name != i.name || o.path != i.path) continue;
            if (!o.transform.matrix().isApprox(i.transform.matrix(), 1e-9)) continue;
            if (own.bodies[i.body].faces.size() != occt.bodies[o.body].faces.size()) continue;
            taken[k] = found = true;
        }
        EXPECT_TRUE(found) << what << ": own instance " << i.name << " at "
                           << i.transform.translation().transpose() << " is none of OCCT's";
    }
}

// The boxes of the flattened model's faces per instance (faces of instance k follow
// those of instance k - 1, `faces_per_body` each).
std::vector<Eigen::AlignedBox3d> instance_boxes(const geom::Model& model, std::size_t faces_per_body) {
    const tess::TessellationResult result = mesh_at(geom::flatten_instances(model), 0.01);
    EXPECT_TRUE(result.failed_faces.empty());
    std::vector<Eigen::AlignedBox3d> boxes(model.instances.size());
    for (std::size_t t = 0; t < result.mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            boxes[static_cast<std::size_t>(result.mesh.face_ids[t]) / faces_per_body].extend(
                result.mesh.positions[result.mesh.triangles[t][k]]);
    return boxes;
}

TEST(OwnStepReader, PlacesAPartTwiceAsOcctDoes) {
    REQUIRE_OCCT();
    const BoxPair pair;
    const std::string path = temp_path("own_pair.stp");
    pair.write(path);
    const geom::Model own = io::read_step(path, own_reader());
    const geom::Model occt = io::read_step(path);
    ASSERT_EQ(own.bodies.size(), 1u);  // the part once
    EXPECT_EQ(own.bodies[0].name, "block");
    ASSERT_EQ(own.instances.size(), 2u);
    expect_same_instances(own, occt, "pair");
    // Where the placements put the boxes: t1; turned 90° about z, then t2.
    const std::vector<Eigen::AlignedBox3d> boxes = instance_boxes(own, 6);
    pair.expect_boxes(boxes[0], boxes[1]);
    std::filesystem::remove(path);
}

TEST(OwnStepReader, ComposesTheTransformsOfANestedAssembly) {
    REQUIRE_OCCT();
    const double dx = 10, dy = 4, dz = 2;
    const Eigen::Vector3d t1(100, 0, 0), t2(0, 50, 7), s1(0, 0, 300), s2(-40, 20, 0);
    const std::string path = temp_path("own_nested.stp");
    test::write_nested_box_assembly_step(path, dx, dy, dz, t1, t2, s1, s2);
    const geom::Model own = io::read_step(path, own_reader());
    const geom::Model occt = io::read_step(path);
    ASSERT_EQ(own.bodies.size(), 1u);
    ASSERT_EQ(own.instances.size(), 4u);
    expect_same_instances(own, occt, "top");
    for (const geom::Instance& i : own.instances) {
        ASSERT_EQ(i.path.size(), 2u);
        EXPECT_EQ(i.path[0], "top");
    }
    // Outer placement after inner: the 4 boxes' corners nearest -infinity, derived.
    const Eigen::Affine3d outer2 = Eigen::Translation3d(s2) * Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitX());
    std::vector<Eigen::AlignedBox3d> expected;
    for (const Eigen::Affine3d& outer : {Eigen::Affine3d(Eigen::Translation3d(s1)), outer2})
        for (const Eigen::Vector3d& inner : {t1, t2}) {
            Eigen::AlignedBox3d box;
            for (int c = 0; c < 8; ++c)
                box.extend(outer * (inner + Eigen::Vector3d(c & 1 ? dx : 0, c & 2 ? dy : 0, c & 4 ? dz : 0)));
            expected.push_back(box);
        }
    const std::vector<Eigen::AlignedBox3d> boxes = instance_boxes(own, 6);
    for (const Eigen::AlignedBox3d& e : expected) {
        const bool placed = std::any_of(boxes.begin(), boxes.end(), [&e](const Eigen::AlignedBox3d& b) {
            return b.min().isApprox(e.min(), 1e-9) && b.max().isApprox(e.max(), 1e-9);
        });
        EXPECT_TRUE(placed) << "no box at " << e.min().transpose() << " .. " << e.max().transpose();
    }
    std::filesystem::remove(path);
}

// Placements are lengths: a file in centimetres puts the boxes 10 times as far (mm).
TEST(OwnStepReader, ScalesPlacementsWithTheFilesLengthUnit) {
    REQUIRE_OCCT();
    const Eigen::Vector3d t1(100, 0, 0), t2(0, 50, 7);
    const std::string mm = temp_path("own_pair_mm.stp"), cm = temp_path("own_pair_cm.stp");
    test::write_box_assembly_step(mm, 10, 4, 2, t1, t2);
    std::string text = read_text(mm);
    ASSERT_NE(text.find(".MILLI."), std::string::npos);
    for (std::size_t at = text.find(".MILLI."); at != std::string::npos; at = text.find(".MILLI.", at))
        text.replace(at, 7, ".CENTI.");  // every representation context's unit
    write_text(cm, text);
    const geom::Model own = io::read_step(cm, own_reader());
    const geom::Model occt = io::read_step(cm);
    ASSERT_EQ(own.instances.size(), 2u);
    expect_same_instances(own, occt, "pair in cm");
    EXPECT_TRUE(own.instances[0].transform.translation().isApprox(10 * t1, 1e-9))
        << own.instances[0].transform.translation().transpose();
    std::filesystem::remove(mm);
    std::filesystem::remove(cm);
}

// The product definitions of the first NEXT_ASSEMBLY_USAGE_OCCURRENCE in `text`:
// relating (the assembly) and related (the part), as "#12".
std::pair<std::string, std::string> first_component(const std::string& text) {
    const std::size_t at = text.find("NEXT_ASSEMBLY_USAGE_OCCURRENCE(");
    const std::size_t end = text.find(')', at);
    std::vector<std::string> refs;
    for (std::size_t h = text.find('#', at); h < end; h = text.find('#', h + 1))
        refs.push_back(text.substr(h, text.find_first_of(",)", h) - h));
    return refs.size() >= 2 ? std::make_pair(refs[0], refs[1]) : std::make_pair(std::string(), std::string());
}

TEST(OwnStepReader, AnAssemblyThatContainsItselfIsAReadErrorWithItsLine) {
    REQUIRE_OCCT();
    const std::string path = temp_path("own_cycle.stp");
    test::write_box_assembly_step(path, 10, 4, 2, {100, 0, 0}, {0, 50, 7});
    std::string text = read_text(path);
    const auto [assembly, part] = first_component(text);
    ASSERT_FALSE(assembly.empty());
    // The part made a component of its own assembly's: pair -> block -> pair.
    const std::size_t data_end = text.rfind("ENDSEC;");
    const std::string cycle = "#999999 = NEXT_ASSEMBLY_USAGE_OCCURRENCE('9','loop','',";
    text.insert(data_end, cycle + part + "," + assembly + ",$);\n");
    write_text(path, text);
    // The error names the line of one of the cycle's two NEXT_ASSEMBLY_USAGE_OCCURRENCEs.
    const auto line_of = [&text](std::size_t at) {
        return static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n')) + 1;
    };
    const int original = line_of(text.find("NEXT_ASSEMBLY_USAGE_OCCURRENCE(")), added = line_of(data_end);
    try {
        io::read_step(path, own_reader());
        ADD_FAILURE() << "a cyclic assembly was read";
    } catch (const geom::ReadError& e) {
        EXPECT_EQ(e.file(), path);
        EXPECT_TRUE(e.line() == original || e.line() == added) << e.what();
        EXPECT_NE(e.reason().find("contains itself"), std::string::npos) << e.what();
    }
    std::filesystem::remove(path);
}

// 18 levels each holding the one below twice: 2^18 = 262144 occurrences of one box,
// more than kMaxStepOccurrences (200000): an error, not 262144 instances.
TEST(OwnStepReader, AnExplodingAssemblyIsAReadError) {
    REQUIRE_OCCT();
    const std::string path = temp_path("own_doubling.stp");
    test::write_doubling_assembly_step(path, 18);
    try {
        io::read_step(path, own_reader());
        ADD_FAILURE() << "2^18 occurrences were read";
    } catch (const geom::ReadError& e) {
        EXPECT_NE(e.reason().find("more than 200000"), std::string::npos) << e.what();
    }
    // 10 levels: 1024 instances of one body, the last box 2 + 4 + ... + 1024 along x.
    test::write_doubling_assembly_step(path, 10);
    const geom::Model model = io::read_step(path, own_reader());
    EXPECT_EQ(model.bodies.size(), 1u);
    ASSERT_EQ(model.instances.size(), 1024u);
    double far = 0;
    for (const geom::Instance& i : model.instances) far = std::max(far, i.transform.translation().x());
    EXPECT_DOUBLE_EQ(far, 2046.0);
    std::filesystem::remove(path);
}

// A part whose shape maps another representation twice (MAPPED_ITEM, ISO 10303-43
// mapped_item): the plate's ADVANCED_BREP_SHAPE_REPRESENTATION written once, placed at
// (200, 0, 0) and, turned 90° about z, at (0, 0, 50). One body, two instances, the
// flattened plates where the maps put them and where OCCT's reader puts them.
TEST(OwnStepReader, PlacesAMappedRepresentationByItsMaps) {
    REQUIRE_OCCT();
    const double L = 100, W = 60, H = 10;
    const std::string path = temp_path("own_mapped.stp");
    test::write_plate_with_holes_step(path, L, W, H, {{20, 30}, {50, 30}, {80, 30}}, 8);
    std::string text = read_text(path);
    // "#10 = ADVANCED_BREP_SHAPE_REPRESENTATION('',(#11,#15),#415);": its name and context.
    const std::size_t absr = text.find("ADVANCED_BREP_SHAPE_REPRESENTATION(");
    ASSERT_NE(absr, std::string::npos);
    const std::size_t hash = text.rfind('#', absr);
    const std::string rep = text.substr(hash, text.find_first_of(" =", hash) - hash);
    const std::size_t close = text.find(");", absr);
    const std::size_t context_at = text.rfind('#', close);
    const std::string context = text.substr(context_at, close - context_at);
    const std::size_t sdr = text.find("SHAPE_DEFINITION_REPRESENTATION(");
    const std::size_t sdr_rep = text.find("," + rep + ")", sdr);
    ASSERT_NE(sdr_rep, std::string::npos);
    text.replace(sdr_rep, rep.size() + 2, ",#900012)");
    const std::string maps =
        "#900001 = CARTESIAN_POINT('',(0.,0.,0.));\n#900002 = DIRECTION('',(0.,0.,1.));\n"
        "#900003 = DIRECTION('',(1.,0.,0.));\n#900004 = AXIS2_PLACEMENT_3D('',#900001,#900002,#900003);\n"
        "#900005 = CARTESIAN_POINT('',(200.,0.,0.));\n#900006 = AXIS2_PLACEMENT_3D('',#900005,#900002,#900003);\n"
        "#900007 = CARTESIAN_POINT('',(0.,0.,50.));\n#900013 = DIRECTION('',(0.,1.,0.));\n"
        "#900008 = AXIS2_PLACEMENT_3D('',#900007,#900002,#900013);\n"
        "#900009 = REPRESENTATION_MAP(#900004," + rep + ");\n#900010 = MAPPED_ITEM('a',#900009,#900006);\n"
        "#900011 = MAPPED_ITEM('b',#900009,#900008);\n"
        "#900012 = SHAPE_REPRESENTATION('',(#900010,#900011,#900004)," + context + ");\n";
    text.insert(text.rfind("ENDSEC;"), maps);
    write_text(path, text);
    const geom::Model own = io::read_step(path, own_reader());
    const geom::Model occt = io::read_step(path);
    ASSERT_EQ(own.bodies.size(), 1u);
    ASSERT_EQ(own.instances.size(), 2u);
    const std::size_t faces = own.bodies[0].faces.size();
    const std::vector<Eigen::AlignedBox3d> boxes = instance_boxes(own, faces);
    EXPECT_TRUE(boxes[0].min().isApprox(Eigen::Vector3d(200, 0, 0), 1e-9)) << boxes[0].min().transpose();
    EXPECT_TRUE(boxes[0].max().isApprox(Eigen::Vector3d(200 + L, W, H), 1e-9)) << boxes[0].max().transpose();
    EXPECT_TRUE(boxes[1].min().isApprox(Eigen::Vector3d(-W, 0, 50), 1e-9)) << boxes[1].min().transpose();
    EXPECT_TRUE(boxes[1].max().isApprox(Eigen::Vector3d(0, L, 50 + H), 1e-9)) << boxes[1].max().transpose();
    // OCCT's reader: the same faces, placed the same (its model may keep them as bodies).
    const geom::Model own_flat = geom::flatten_instances(own), occt_flat = geom::flatten_instances(occt);
    EXPECT_EQ(own_flat.faces.size(), occt_flat.faces.size());
    const double T = 0.01;
    const tess::TessellationResult a = mesh_at(own_flat, T), b = mesh_at(occt_flat, T);
    Eigen::AlignedBox3d own_box, occt_box;
    for (const Eigen::Vector3d& p : a.mesh.positions) own_box.extend(p);
    for (const Eigen::Vector3d& p : b.mesh.positions) occt_box.extend(p);
    EXPECT_TRUE(own_box.min().isApprox(occt_box.min(), 1e-6) && own_box.max().isApprox(occt_box.max(), 1e-6))
        << own_box.min().transpose() << " .. " << own_box.max().transpose() << " vs OCCT's "
        << occt_box.min().transpose() << " .. " << occt_box.max().transpose();
    EXPECT_NEAR(mesh_area(a.mesh), mesh_area(b.mesh), 4e-3 * mesh_area(b.mesh));
    std::filesystem::remove(path);
}

// The shared assemblies: as many bodies as OCCT's reader gives (each part once) and
// the same instances (names, paths, transforms).
TEST(OwnStepReader, ReadsTheSharedAssembliesAsOcctDoes) {
    REQUIRE_OCCT();
    for (const char* name : {"step/as1-oc-214-mat.stp", "step/bug24283_spheres.stp", "step/xr1-tc-blt.stp",
                             "step/xr1-tc-nut.stp", "step/xr1-tc-rod.stp"}) {
        TRIMKIT_CAD_SAMPLE(path, name);
        const geom::Model own = io::read_step(path, own_reader());
        const geom::Model occt = io::read_step(path);
        EXPECT_EQ(own.bodies.size(), occt.bodies.size()) << name;
        EXPECT_EQ(own.faces.size(), occt.faces.size()) << name;
        expect_same_instances(own, occt, name);
    }
}

}  // namespace
}  // namespace trimkit
#else
TEST(OcctModels, NeedOpenCascade) { GTEST_SKIP() << "trimkit built without Open CASCADE"; }
#endif
