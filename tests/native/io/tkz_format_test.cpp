// io/tkz_format and io/write_iges: the compress -> .tkz -> extend round trip
// ([Muraki] Sec. 2-3) and hostile .tkz input (truncations, huge counts, bad indices).
#include "io/tkz_format.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>

#include "fit/evaluate_fit.h"
#include "fit/edge_faces.h"
#include "fit/extend_model.h"
#include "fit/judge_g1.h"
#include "fit/surface_deviation.h"
#include "fit/fit_models.h"
#include "geom/error.h"
#include "io/read_iges.h"
#include "io/write_iges.h"

namespace trimkit::io {
namespace {

// The G1 strip with the plate beside it: 4 faces, some compressed, some kept.
geom::Model mixed_model() {
    geom::Model m = fit::test::g1_strip();
    const geom::Model plate = fit::test::plate_with_holes();
    geom::Face f = plate.faces[0];
    const int offset = static_cast<int>(m.edges.size());
    for (auto& loop : f.loops)
        for (auto& c : loop.coedges) c.edge += offset;
    m.edges.insert(m.edges.end(), plate.edges.begin(), plate.edges.end());
    m.faces.push_back(f);
    m.free_faces.push_back(3);
    return m;
}

bool same_surface(const geom::NurbsSurface& a, const geom::NurbsSurface& b) {
    return a.points() == b.points() && a.knots_u() == b.knots_u() && a.knots_v() == b.knots_v() &&
           a.weights() == b.weights() && a.degree_u() == b.degree_u() && a.degree_v() == b.degree_v();
}

TEST(Tkz, RoundTripRebuildsCompressedFacesAndKeepsTheOthersBitForBit) {
    const geom::Model m = mixed_model();
    std::vector<fit::FaceCompression> report;
    const fit::CompressedModel c = fit::compress_model(m, {}, &report);
    int compressed = 0;
    for (const auto& r : report) compressed += r.compressed;
    ASSERT_GE(compressed, 2);
    ASSERT_LT(compressed, 4) << "G1 neighbours of a compressed face keep their surface";
    const std::string bytes = tkz_bytes(c);
    const fit::CompressedModel back = read_tkz_bytes(bytes, "mixed.tkz");
    ASSERT_EQ(back.model.faces.size(), m.faces.size());
    EXPECT_EQ(tkz_bytes(back), bytes) << "reading and writing again gives the same bytes";
    const geom::Model e = fit::extend_model(back);
    const geom::Model direct = fit::extend_model(c);
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
        if (report[f].compressed) {
            EXPECT_TRUE(same_surface(e.faces[f].surface, direct.faces[f].surface)) << "face " << f << ": same refit";
            const fit::FitError err = fit::evaluate_fit(c.model.faces[f], c.model.edges, e.faces[f].surface);
            EXPECT_LE(err.max(), report[f].tolerance) << "face " << f;
        } else {
            EXPECT_TRUE(same_surface(e.faces[f].surface, m.faces[f].surface)) << "face " << f;
            EXPECT_EQ(e.faces[f].loops[0].coedges[0].curve.points(), m.faces[f].loops[0].coedges[0].curve.points());
        }
    }
    // Compressed smaller than the same file with every surface kept.
    const fit::CompressedModel kept{c.model, std::vector<std::optional<fit::FitRule>>(m.faces.size())};
    EXPECT_LT(bytes.size(), tkz_bytes(kept).size());
}

TEST(Tkz, ExtendedModelWrittenAsIgesReadsBackWithinTolerance) {
    const geom::Model m = mixed_model();
    std::vector<fit::FaceCompression> report;
    const fit::CompressedModel c = fit::compress_model(m, {}, &report);
    const geom::Model e = fit::extend_model(read_tkz_bytes(tkz_bytes(c), "mixed.tkz"));
    const geom::Model back = read_iges_text(iges_text(e, "mixed.igs"), "mixed.igs");
    ASSERT_EQ(back.faces.size(), m.faces.size());
    for (std::size_t f = 0; f < m.faces.size(); ++f) {
        EXPECT_EQ(back.faces[f].loops.size(), m.faces[f].loops.size()) << "face " << f;
        const fit::FitError err = fit::evaluate_fit(c.model.faces[f], c.model.edges, back.faces[f].surface);
        if (report[f].compressed) EXPECT_LE(err.max(), report[f].tolerance) << "face " << f;
        else EXPECT_TRUE(same_surface(back.faces[f].surface, m.faces[f].surface)) << "face " << f << " kept";
    }
}

TEST(WriteIges, BodiesWithEdgesAreWrittenAsBrepAndKeepTheirSharedEdges) {
    // The G1 strip as an open shell: 514 of 510 faces on one 504 edge list. Read
    // back, the faces still share their edges, so the middle face is judged G1 again.
    geom::Model m = fit::test::g1_strip();
    m.bodies.push_back({"strip", {0, 1, 2}, false});
    m.free_faces.clear();
    const std::string text = iges_text(m, "strip.igs");
    EXPECT_NE(text.find("     514"), std::string::npos);
    const geom::Model back = read_iges_text(text, "strip.igs");
    ASSERT_EQ(back.faces.size(), 3u);
    ASSERT_EQ(back.bodies.size(), 1u);
    std::vector<int> uses(back.edges.size(), 0);
    for (const auto& f : back.faces)
        for (const auto& loop : f.loops)
            for (const auto& c : loop.coedges)
                if (c.edge >= 0) ++uses[c.edge];
    EXPECT_EQ(std::count(uses.begin(), uses.end(), 2), 3) << "the left edge and both pieces of the right";
    const fit::EdgeFaces ef = fit::edge_faces(back);
    const auto g1 = fit::judge_g1(back, ef, 1);
    int smooth = 0;
    for (const auto& loop : g1) smooth += static_cast<int>(std::count(loop.begin(), loop.end(), true));
    EXPECT_EQ(smooth, 3);
    for (int f = 0; f < 3; ++f) {
        const fit::SurfaceDeviation d = fit::surface_deviation(m.faces[f], back.faces[f].surface);
        EXPECT_LT(d.max, 1e-12) << f;
    }
}

void expect_read_error(const std::string& bytes, const std::string& needle) {
    try {
        read_tkz_bytes(bytes, "bad.tkz");
        ADD_FAILURE() << "no error for " << needle;
    } catch (const geom::ReadError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("bad.tkz: ", 0), 0u) << e.what();
        EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
}

TEST(Tkz, NotesKeepWarningsSourceEntitiesAndAssemblyPaths) {
    geom::Model m = fit::test::plate_with_holes();
    m.warnings = {"entity 140 at D123 unsupported"};
    m.faces[0].source_entity = 17;
    m.faces[0].warnings = {"trim curve 1 projected from model space", "loop repaired"};
    m.bodies.push_back({"plate", {0}, false});
    m.free_faces.clear();
    geom::Instance placed;
    placed.body = 0;
    placed.name = "plate:1";
    placed.path = {"assembly", "sub-assembly"};
    m.instances.push_back(placed);
    const fit::CompressedModel all_kept{m, std::vector<std::optional<fit::FitRule>>(m.faces.size())};
    const geom::Model back = read_tkz_bytes(tkz_bytes(all_kept), "notes.tkz").model;
    EXPECT_EQ(back.warnings, m.warnings);
    EXPECT_EQ(back.faces[0].source_entity, 17);
    EXPECT_EQ(back.faces[0].warnings, m.faces[0].warnings);
    ASSERT_EQ(back.instances.size(), 1u);
    EXPECT_EQ(back.instances[0].path, placed.path);
    EXPECT_TRUE(same_surface(back.faces[0].surface, m.faces[0].surface));
}

TEST(Tkz, VersionOneFilesWithoutNotesStillRead) {
    // A model without warnings, faces or instances: its notes are one count (4 bytes).
    geom::Model m;
    m.colors.push_back({{0.1, 0.2, 0.3}, "red"});
    std::string bytes = tkz_bytes({m, {}});
    bytes.resize(bytes.size() - 4);
    bytes[4] = 1;  // the version, little-endian
    const geom::Model back = read_tkz_bytes(bytes, "v1.tkz").model;
    ASSERT_EQ(back.colors.size(), 1u);
    EXPECT_EQ(back.colors[0].name, "red");
    bytes[4] = 3;
    expect_read_error(bytes, "versions 1 and 2");
}

TEST(Tkz, HostileInputGivesAClearError) {
    std::vector<fit::FaceCompression> report;
    const std::string good = tkz_bytes(fit::compress_model(fit::test::plate_with_holes(), {}, &report));
    expect_read_error("", "truncated");
    expect_read_error("IGES" + good.substr(4), "not a .tkz file");
    for (std::size_t n = 0; n < good.size(); n += 7) {
        EXPECT_THROW(read_tkz_bytes(good.substr(0, n), "bad.tkz"), geom::ReadError) << n;
    }
    // The edge count (after magic, version, units "mm" and the scale) set to 2^32 - 1.
    std::string huge = good;
    const std::size_t at = 4 + 4 + 4 + 2 + 8;
    std::memset(&huge[at], 0xff, 4);
    expect_read_error(huge, "edge count");
    // The first edge's curve point count set to 2^31.
    std::string points = good;
    const std::size_t count_at = at + 4 + 1 + 1;
    std::memcpy(&points[count_at], "\x00\x00\x00\x80", 4);
    expect_read_error(points, "bytes are left");
    expect_read_error(good + "x", "after the end");
}

TEST(Tkz, EveryByteFlippedIsReadOrRefusedNeverACrash) {
    // Every 3rd byte of a small file set to 0x00 and 0xff in turn: the reader returns a
    // model or throws ReadError; one in 40 models that read is also extended (a fit is
    // ~50 ms), which ends or throws a geom error (a degenerate fit), nothing else.
    std::vector<fit::FaceCompression> report;
    const std::string good = tkz_bytes(fit::compress_model(fit::test::concave_face(), {}, &report));
    ASSERT_TRUE(report[0].compressed);
    int read = 0, refused = 0;
    for (std::size_t i = 0; i < good.size(); i += 3)
        for (const unsigned char value : {0x00, 0xff}) {
            std::string bad = good;
            bad[i] = static_cast<char>(value);
            try {
                const fit::CompressedModel m = read_tkz_bytes(bad, "bad.tkz");
                if (++read % 40 != 0) continue;
                try {
                    fit::extend_model(m);
                } catch (const geom::InvalidInput&) {
                } catch (const geom::NumericalFailure&) {
                }
            } catch (const geom::ReadError&) {
                ++refused;
            }
        }
    std::printf("%zu bytes: %d variants read, %d refused\n", good.size(), read, refused);
    EXPECT_GT(refused, 0);
}

}  // namespace
}  // namespace trimkit::io
