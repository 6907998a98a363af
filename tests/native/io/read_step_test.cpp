// read_step: the STEP samples in ../shared/data/cad/step/ against Open CASCADE's face
// counts (bench/occt_reference/RESULTS.md, faces once per placement), finite surface
// evaluation, closed trim loops, shared edges and units. Skips with a reason when trimkit
// is built without OCCT or the samples are absent; the stub's refusal is tested then.
#include "io/read_step.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "geom/error.h"
#include "geom/flatten_instances.h"
#include "io/read_model.h"

namespace trimkit::io {
namespace {

const std::string kStepDir = std::string(TRIMKIT_CAD_DIR) + "/step";

// Faces OCCT 7.6.3 makes from each file (STEPControl_Reader, default settings).
const std::vector<std::pair<std::string, int>> kOcctStepFaceCounts = {
    {"as1-oc-214-mat.stp", 160}, {"bm2_ec_exhaust-A.stp", 58}, {"bm2_ec_lever-A.stp", 49},
    {"bug32596_abc_0_13.step", 99}, {"ec_turbine-A.stp", 53}, {"linkrods.step", 37},
    {"screw.step", 10}, {"xr1-tc-blt.stp", 7}, {"xr1-tc-nut.stp", 8}, {"xr1-tc-rod.stp", 4},
};

// Skips the current test unless STEP is supported and `file` exists; returns its path.
#define REQUIRE_STEP_FILE(path_var, file)                                                 \
    if (!step_supported()) GTEST_SKIP() << "trimkit built without Open CASCADE";           \
    const std::string path_var = kStepDir + "/" + (file);                                 \
    if (!std::filesystem::exists(path_var)) GTEST_SKIP() << path_var << " not found"

TEST(ReadStep, WithoutOcctRefusesWithReadError) {
    if (step_supported()) GTEST_SKIP() << "trimkit built with Open CASCADE";
    try {
        read_step("part.step");
        ADD_FAILURE() << "no ReadError";
    } catch (const geom::ReadError& e) {
        EXPECT_EQ(e.file(), "part.step");
        EXPECT_NE(e.reason().find("Open CASCADE"), std::string::npos) << e.what();
    }
}

TEST(ReadStep, ReadModelDispatchesStepExtensions) {
    try {
        read_model("/nonexistent/part.STEP");
        ADD_FAILURE() << "no ReadError";
    } catch (const geom::ReadError& e) {
        EXPECT_EQ(std::string(e.what()).find("unsupported file type"), std::string::npos) << e.what();
    }
}

TEST(ReadStep, MissingOrBrokenFileIsReadError) {
    if (!step_supported()) GTEST_SKIP() << "trimkit built without Open CASCADE";
    EXPECT_THROW(read_step("/nonexistent/part.stp"), geom::ReadError);
    const std::string bad = (std::filesystem::temp_directory_path() / "trimkit_bad.step").string();
    {
        std::FILE* f = std::fopen(bad.c_str(), "w");
        ASSERT_NE(f, nullptr);
        std::fputs("this is not STEP\n", f);
        std::fclose(f);
    }
    EXPECT_THROW(read_step(bad), geom::ReadError);
    // The messages say what is wrong, not only that OCCT failed.
    try {
        read_step(bad);
    } catch (const geom::ReadError& e) {
        EXPECT_NE(e.reason().find("not a STEP file"), std::string::npos) << e.what();
    }
    try {
        read_step("/nonexistent/part.stp");
    } catch (const geom::ReadError& e) {
        EXPECT_NE(e.reason().find("cannot open"), std::string::npos) << e.what();
    }
    // A STEP file with a dangling reference: OCCT's own check message is passed on.
    {
        std::FILE* f = std::fopen(bad.c_str(), "w");
        ASSERT_NE(f, nullptr);
        std::fputs("ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n#2=FOO_BAR(#99);\nENDSEC;\nEND-ISO-10303-21;\n", f);
        std::fclose(f);
    }
    try {
        read_step(bad);
        ADD_FAILURE() << "no ReadError";
    } catch (const geom::ReadError& e) {
        EXPECT_NE(e.reason().find("#99"), std::string::npos) << e.what();
    }
    std::filesystem::remove(bad);
}

std::string file_text(const std::string& path) {
    std::ifstream in(path);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// `text` written to `name` in the temporary folder; its path.
std::string temp_file(const std::string& name, const std::string& text) {
    const std::string path = (std::filesystem::temp_directory_path() / name).string();
    std::ofstream(path) << text;
    return path;
}

// One damaged type name (VERTEX_POINT -> VERTEX_(OINT) made OCCT 7.6 dereference a null
// handle during the transfer and killed the process; now it is a read error. Then a
// good file still reads (the process's signal handlers are back in place).
TEST(ReadStep, DamagedEntityIsReadErrorNotACrash) {
    REQUIRE_STEP_FILE(path, "xr1-tc-nut.stp");
    std::string text = file_text(path);
    const std::size_t at = text.find("#20=VERTEX_POINT");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 16, "#20=VERTEX_(OINT");
    const std::string bad = temp_file("trimkit_damaged_nut.stp", text);
    EXPECT_THROW(read_step(bad), geom::ReadError);
    std::filesystem::remove(bad);
    EXPECT_EQ(read_step(path).faces.size(), 8u);
}

// A real file with one entity defined a second time (Part 21 names each entity once;
// OCCT reads such a file and its transfer can recurse without end, fuzz finding 9) is
// refused before OCCT sees it, naming the line of the second definition.
TEST(ReadStep, EntityDefinedTwiceIsReadErrorWithItsLine) {
    REQUIRE_STEP_FILE(path, "xr1-tc-nut.stp");
    std::string text = file_text(path);
    const std::size_t at = text.find("#20=VERTEX_POINT");
    ASSERT_NE(at, std::string::npos);
    const std::string definition = text.substr(at, text.find('\n', at) + 1 - at);
    const std::size_t end = text.find("ENDSEC;", at);
    ASSERT_NE(end, std::string::npos);
    text.insert(end, definition);
    const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(end), '\n'));
    const std::string bad = temp_file("trimkit_twice_nut.stp", text);
    try {
        read_step(bad);
        ADD_FAILURE() << "no ReadError";
    } catch (const geom::ReadError& e) {
        EXPECT_EQ(e.line(), line);
        EXPECT_NE(e.reason().find("entity #20 is defined twice"), std::string::npos) << e.what();
    }
    std::filesystem::remove(bad);
    EXPECT_EQ(read_step(path).faces.size(), 8u);
}

TEST(ReadStep, FaceCountsMatchOpenCascade) {
    if (!step_supported()) GTEST_SKIP() << "trimkit built without Open CASCADE";
    if (!std::filesystem::exists(kStepDir)) GTEST_SKIP() << kStepDir << " not found";
    for (const auto& [file, faces] : kOcctStepFaceCounts) {
        const std::string path = kStepDir + "/" + file;
        if (!std::filesystem::exists(path)) continue;
        const geom::Model m = read_step(path);
        // OCCT counts each placed face; trimkit reads a part once and places it.
        EXPECT_EQ(static_cast<int>(geom::flatten_instances(m).faces.size()), faces) << file;
        EXPECT_TRUE(m.warnings.empty()) << file << ": " << m.warnings.front();
        EXPECT_EQ(m.units, "mm");
        EXPECT_DOUBLE_EQ(m.scale_to_metres, 1e-3);
        size_t in_bodies = m.free_faces.size();
        for (const auto& body : m.bodies) in_bodies += body.faces.size();
        EXPECT_EQ(in_bodies, m.faces.size()) << file;
    }
}

TEST(ReadStep, FacesEvaluateFiniteAndLoopsClose) {
    if (!step_supported()) GTEST_SKIP() << "trimkit built without Open CASCADE";
    if (!std::filesystem::exists(kStepDir)) GTEST_SKIP() << kStepDir << " not found";
    for (const auto& [file, faces] : kOcctStepFaceCounts) {
        const std::string path = kStepDir + "/" + file;
        if (!std::filesystem::exists(path)) continue;
        const geom::Model m = read_step(path);
        for (size_t f = 0; f < m.faces.size(); ++f) {
            const geom::Face& face = m.faces[f];
            const auto [u0, u1] = face.surface.domain_u();
            const auto [v0, v1] = face.surface.domain_v();
            for (int i = 0; i <= 4; ++i)
                for (int j = 0; j <= 4; ++j) {
                    const Eigen::Vector3d p =
                        face.surface.evaluate(u0 + (u1 - u0) * i / 4, v0 + (v1 - v0) * j / 4);
                    ASSERT_TRUE(p.allFinite()) << file << " face " << f;
                }
            ASSERT_FALSE(face.loops.empty()) << file << " face " << f;
            EXPECT_TRUE(face.loops.front().outer) << file << " face " << f;
            // Gaps between consecutive coedges, relative to the domain's size.
            const double tol = 1e-4 * std::max(u1 - u0, v1 - v0);
            for (const auto& loop : face.loops) {
                const size_t n = loop.coedges.size();
                for (size_t k = 0; k < n; ++k) {
                    const auto& a = loop.coedges[k].curve;
                    const auto& b = loop.coedges[(k + 1) % n].curve;
                    const double gap =
                        (a.evaluate(a.domain().second) - b.evaluate(b.domain().first)).norm();
                    EXPECT_LE(gap, tol) << file << " face " << f << " coedge " << k;
                }
            }
        }
    }
}

// as1-oc-214-mat.stp (an AP214 assembly): each part is one body, read once, named after
// its product, and placed by instances named after the occurrences (XCAF). The file's
// tree: as1 = plate + 2 l-bracket-assembly (l-bracket + 3 nut-bolt-assembly (bolt +
// nut)) + rod-assembly (rod + 2 nut): 5 parts, 18 placements. Its five STYLED_ITEMs
// colour the five solids, one colour each: the rod COLOUR_RGB(1, 0.5, 0), the plate's
// solid (#3813, in the representation of the plate's context #6195) COLOUR_RGB(0.8, 1, 0),
// the others pre-defined red, green and blue. (Reading placed shapes, the earlier
// reader missed the plate's colour.)
TEST(ReadStep, AssemblyPartsAreNamedColouredAndPlaced) {
    REQUIRE_STEP_FILE(path, "as1-oc-214-mat.stp");
    const geom::Model m = read_step(path);
    ASSERT_EQ(m.bodies.size(), 5u);
    ASSERT_EQ(m.instances.size(), 18u);
    std::map<std::string, int> placements;
    std::map<std::string, std::set<int>> part_colors;
    for (const geom::Instance& i : m.instances) ++placements[m.bodies[i.body].name];
    for (const geom::Body& b : m.bodies)
        for (int f : b.faces) {
            ASSERT_LT(m.faces[f].color, static_cast<int>(m.colors.size()));
            part_colors[b.name].insert(m.faces[f].color);
        }
    EXPECT_EQ(placements, (std::map<std::string, int>{{"bolt", 6}, {"l-bracket", 2}, {"nut", 8}, {"plate", 1},
                                                      {"rod", 1}}));
    // Every placement lies below the root assembly, the nuts of the bolts two levels down.
    int deepest = 0;
    for (const geom::Instance& i : m.instances) {
        ASSERT_FALSE(i.path.empty());
        EXPECT_EQ(i.path.front(), "as1");
        deepest = std::max(deepest, static_cast<int>(i.path.size()));
    }
    EXPECT_EQ(deepest, 3);
    std::set<int> distinct;
    for (const auto& [name, colors] : part_colors) {
        ASSERT_EQ(colors.size(), 1u) << name;  // one colour per part, on every face
        ASSERT_GE(*colors.begin(), 0) << name;
        distinct.insert(*colors.begin());
    }
    EXPECT_EQ(distinct.size(), 5u);
    EXPECT_EQ(m.colors.size(), 5u);
    const auto& rod = m.colors[*part_colors["rod"].begin()].rgb;
    EXPECT_NEAR(rod[0], 1.0, 1e-6);
    EXPECT_NEAR(rod[1], 0.5, 1e-6);
    EXPECT_NEAR(rod[2], 0.0, 1e-6);
    const auto& plate = m.colors[*part_colors["plate"].begin()].rgb;
    EXPECT_NEAR(plate[0], 0.8, 1e-6);
    EXPECT_NEAR(plate[1], 1.0, 1e-6);
    EXPECT_NEAR(plate[2], 0.0, 1e-6);
}

TEST(ReadStep, ScrewSharesEdgesAndPlacesCurvesOnSurfaces) {
    REQUIRE_STEP_FILE(path, "screw.step");
    const geom::Model m = read_step(path);
    ASSERT_EQ(m.faces.size(), 10u);
    ASSERT_FALSE(m.edges.empty());
    // Every non-degenerate shared edge is used by two coedges (closed solid).
    std::vector<int> uses(m.edges.size(), 0);
    for (const auto& face : m.faces)
        for (const auto& loop : face.loops)
            for (const auto& c : loop.coedges) {
                ASSERT_GE(c.edge, 0);
                ASSERT_LT(c.edge, static_cast<int>(m.edges.size()));
                ++uses[static_cast<size_t>(c.edge)];
            }
    for (size_t e = 0; e < m.edges.size(); ++e)
        if (m.edges[e].curve) {
            EXPECT_EQ(uses[e], 2) << "edge " << e;
        }
    // The pcurve's start, lifted to the surface, is the edge's end vertex it starts at.
    for (const auto& face : m.faces)
        for (const auto& loop : face.loops)
            for (const auto& c : loop.coedges) {
                const geom::Edge& edge = m.edges[static_cast<size_t>(c.edge)];
                if (!edge.curve || !edge.start || !edge.end) continue;
                const Eigen::Vector2d uv = c.curve.evaluate(c.curve.domain().first);
                const Eigen::Vector3d p = face.surface.evaluate(uv.x(), uv.y());
                const Eigen::Vector3d expected = c.edge_reversed ? *edge.end : *edge.start;
                EXPECT_LE((p - expected).norm(), 1e-3) << p.transpose() << " vs " << expected.transpose();
            }
}

}  // namespace
}  // namespace trimkit::io
