// trimkit's own STEP reader (io/read_step_native.h) on solids built in the test with
// Open CASCADE and written by its STEP writer (occt_models.h): the faces, shared edges
// and bodies it builds, and the mesh of its model against the solid's area by OCCT's
// BRepGProp (an independent measure) and against the model OCCT's reader gives.
// Only with OCCT (the models are made with it; the reader itself needs none).
#include <gtest/gtest.h>

#if TRIMKIT_HAVE_OCCT_MODELS
#include <filesystem>
#include <functional>
#include <string>

#include "io/occt_models.h"
#include "io/read_step.h"
#include "tess/tessellate_model.h"

namespace trimkit {
namespace {

std::string temp_path(const std::string& name) {
    return (std::filesystem::temp_directory_path() / ("trimkit_own_" + name)).string();
}

double mesh_area(const mesh::Mesh& mesh) {
    double area = 0;
    for (const auto& tri : mesh.triangles)
        area += 0.5 * (mesh.positions[tri[1]] - mesh.positions[tri[0]])
                          .cross(mesh.positions[tri[2]] - mesh.positions[tri[0]])
                          .norm();
    return area;
}

tess::TessellationResult mesh_at(const geom::Model& model, double tolerance) {
    tess::TessellationOptions options;
    options.tolerance = tolerance;
    options.threads = 1;
    return tess::tessellate_model(model, options);
}

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
    const std::string path = temp_path(std::string(solid.name) + ".stp");
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
                  return 2 * (100 * 60 - 3 * M_PI * 64) + 2 * 10 * (100 + 60) + 3 * 2 * M_PI * 8 * 10;
              }},
        Solid{"cylinder_cross_hole", [](const std::string& p) { return test::write_cylinder_cross_hole_iges(p, 20, 60, 6); }},
        Solid{"sphere_cut_near_pole",
              [](const std::string& p) { return test::write_sphere_cut_near_pole_iges(p, 25, 5, 3, 4); }},
        Solid{"ball_hole_on_seam", [](const std::string& p) { return test::write_ball_hole_on_seam_iges(p, 30, 6, true); }},
        Solid{"whole_ball", [](const std::string& p) { return test::write_whole_ball_iges(p, 25, true); }},
        Solid{"cone_apex_hole", [](const std::string& p) { return test::write_cone_apex_hole_iges(p, 30, 50, 4, true); }},
        Solid{"filleted_hole_block", [](const std::string& p) { return test::write_filleted_hole_block_iges(p); }},
        Solid{"torus_hole_on_seams", [](const std::string& p) { return test::write_torus_hole_on_seams_iges(p); }},
        Solid{"frustum_hole_on_seam", [](const std::string& p) { return test::write_frustum_hole_on_seam_iges(p); }}),
    [](const ::testing::TestParamInfo<Solid>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace trimkit
#endif
