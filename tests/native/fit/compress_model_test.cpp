// fit/compress_model and extend_model on models built in the test ([Muraki] Sec. 4):
// a planar face with holes, a concave face, and a face between two G1 neighbours
// with a hole across a shared edge. Each rebuilt face is measured as Sec. 4.4 does
// and, along its G1 edges, against its neighbours' normals.
#include "fit/compress_model.h"

#include <gtest/gtest.h>

#include <cmath>

#include "fit/edge_faces.h"
#include "fit/extend_model.h"
#include "fit_models.h"
#include "geom/surface_projector.h"

namespace trimkit::fit {
namespace {

constexpr int kG1Samples = 50;
constexpr double kG1MaxDegrees = 0.5;

// Largest angle (degrees) between the rebuilt face's normal and its neighbour's along
// every coedge the rule marks G1, at kG1Samples points of each edge.
double max_g1_angle(const geom::Model& extended, int face, const FitRule& rule) {
    const EdgeFaces uses = edge_faces(extended);
    const geom::SurfaceProjector own(extended.faces[face].surface);
    double worst = 0;
    for (std::size_t l = 0; l < rule.g1.size(); ++l)
        for (std::size_t c = 0; c < rule.g1[l].size(); ++c) {
            if (!rule.g1[l][c]) continue;
            const int n = neighbour_face(extended, uses, face, static_cast<int>(l), static_cast<int>(c));
            const geom::SurfaceProjector other(extended.faces[n].surface);
            const geom::NurbsCurve3d& e = *extended.edges[extended.faces[face].loops[l].coedges[c].edge].curve;
            for (int k = 0; k < kG1Samples; ++k) {
                const Eigen::Vector3d x = e.evaluate(e.domain().first + (e.domain().second - e.domain().first) * k / (kG1Samples - 1));
                const Eigen::Vector2d a = own.invert(x), b = other.invert(x);
                const double dot = std::abs(own.surface().normal(a.x(), a.y()).dot(other.surface().normal(b.x(), b.y())));
                worst = std::max(worst, std::acos(std::min(1.0, dot)) * 180 / M_PI);
            }
        }
    return worst;
}

// The rebuilt face measured against the source as Sec. 4.4 does.
FitError rebuilt_error(const geom::Model& source, const geom::Model& extended, int face) {
    return evaluate_fit(source.faces[face], source.edges, extended.faces[face].surface);
}

TEST(CompressModel, PlanarFaceWithHolesIsRebuiltExactly) {
    const geom::Model m = test::plate_with_holes();
    std::vector<FaceCompression> report;
    const CompressedModel c = compress_model(m, {}, &report);
    ASSERT_TRUE(report[0].compressed) << report[0].reason;
    EXPECT_EQ(report[0].g1_edges, 0);
    const geom::Model e = extend_model(c);
    const FitError error = rebuilt_error(c.model, e, 0);
    EXPECT_GT(error.grid_points, 300);  // 441 grid points less the holes
    EXPECT_LT(error.max(), 1e-9 * error.box_diagonal) << "a plane is in the fitter's space";
    EXPECT_EQ(e.faces[0].loops.size(), 3u);
}

TEST(CompressModel, ConcaveFaceIsWithinOnePercent) {
    const geom::Model m = test::concave_face();
    std::vector<FaceCompression> report;
    const CompressedModel c = compress_model(m, {}, &report);
    ASSERT_TRUE(report[0].compressed) << report[0].reason;
    const FitError error = rebuilt_error(c.model, extend_model(c), 0);
    std::printf("concave face: avg %.3g max %.3g ratio %.4f%% (%d grid points)\n", error.surface_avg, error.max(),
                100 * error.ratio(), error.grid_points);
    EXPECT_LE(error.max(), report[0].tolerance);
    EXPECT_LT(error.ratio(), 0.01);
}

TEST(CompressModel, FaceBetweenTwoG1NeighboursKeepsG1) {
    const geom::Model m = test::g1_strip();
    CompressOptions options;
    options.faces = {1};
    std::vector<FaceCompression> report;
    const CompressedModel c = compress_model(m, options, &report);
    ASSERT_TRUE(report[1].compressed) << report[1].reason;
    EXPECT_FALSE(report[0].compressed);
    EXPECT_FALSE(report[2].compressed);
    // Judged G1: the left edge (to face 0) and both pieces of the right edge (to face 2).
    const std::vector<bool> expected = {false, true, false, true, false, true};
    EXPECT_EQ(report[1].rule.g1[0], expected);
    const geom::Model e = extend_model(c);
    const double angle = max_g1_angle(e, 1, report[1].rule);
    const FitError error = rebuilt_error(c.model, e, 1);
    std::printf("G1 face: max G1 angle %.4f deg, error avg %.3g max %.3g ratio %.4f%%\n", angle, error.surface_avg,
                error.max(), 100 * error.ratio());
    EXPECT_LT(angle, kG1MaxDegrees);
    EXPECT_LE(error.max(), report[1].tolerance);
    // Kept faces are untouched.
    EXPECT_EQ(e.faces[0].surface.points(), m.faces[0].surface.points());
}

TEST(CompressModel, AbsoluteToleranceBelowTheFitKeepsTheSurface) {
    const geom::Model m = test::concave_face();
    CompressOptions options;
    options.tolerance = 1e-9;
    std::vector<FaceCompression> report;
    const CompressedModel c = compress_model(m, options, &report);
    EXPECT_FALSE(report[0].compressed);
    EXPECT_FALSE(c.rules[0].has_value());
    EXPECT_NE(report[0].reason.find("max error"), std::string::npos) << report[0].reason;
    EXPECT_EQ(c.model.faces[0].loops[0].coedges[0].edge, m.faces[0].loops[0].coedges[0].edge);
}

}  // namespace
}  // namespace trimkit::fit

namespace trimkit::fit {
namespace {

// A half cylinder (radius 2, length 5) bounded by two semicircles and two lines:
// its tangent planes turn by 180°, so no reference plane sees it as a graph
// ([Muraki] Sec. 6), but the Coons patch of its four edges is the cylinder itself.
TEST(CompressModel, HalfCylinderIsRebuiltByTheFourSidedInterpolation) {
    geom::Face f;
    f.surface = geom::cylinder_patch({0, 0, 0}, {0, 0, 1}, {1, 0, 0}, 2.0, 0, M_PI, 0, 5);
    f.loops = {geom::natural_boundary_loop(f.surface)};
    geom::Model m;
    test::add_face(m, f);
    std::vector<FaceCompression> report;
    const CompressedModel c = compress_model(m, {}, &report);
    ASSERT_TRUE(report[0].compressed) << report[0].reason;
    EXPECT_EQ(report[0].rule.method, FitMethod::kCoons);
    const FitError error = rebuilt_error(c.model, extend_model(c), 0);
    // The cubic approximation of a half circle with 4 to 13 control points: well
    // within 1 % of the face's box (diagonal sqrt(4² + 2² + 5²) = 6.7).
    std::printf("half cylinder: %dx%d points, max %.3g (ratio %.4f%%)\n", report[0].rule.count_u,
                report[0].rule.count_v, error.max(), 100 * error.ratio());
    EXPECT_LE(error.max(), report[0].tolerance);
    EXPECT_NEAR(error.box_diagonal, std::sqrt(4.0 * 4 + 2 * 2 + 5 * 5), 0.05);
}

}  // namespace
}  // namespace trimkit::fit

namespace trimkit::fit {
namespace {

geom::Model scaled(const geom::Model& m, double s) {
    geom::Model out = m;
    const Eigen::Affine3d T(Eigen::Scaling(s));
    for (auto& f : out.faces) f.surface = f.surface.transformed(T);
    for (auto& e : out.edges)
        if (e.curve) e.curve = e.curve->transformed(T);
    return out;
}

// The same G1 strip at 1e-6 and 1e6 of its size: the same decisions, rules and G1
// flags, and the same error relative to each face's box (the fit is linear in the
// coordinates; only the projections' Newton tolerances are relative).
TEST(CompressModel, SameDecisionsAtTinyAndHugeScale) {
    const geom::Model m = test::g1_strip();
    std::vector<FaceCompression> base;
    compress_model(m, {}, &base);
    for (const double s : {1e-6, 1e6}) {
        std::vector<FaceCompression> r;
        compress_model(scaled(m, s), {}, &r);
        ASSERT_EQ(r.size(), base.size());
        for (std::size_t f = 0; f < r.size(); ++f) {
            EXPECT_EQ(r[f].compressed, base[f].compressed) << "scale " << s << " face " << f << ": " << r[f].reason;
            EXPECT_EQ(r[f].rule.count_u, base[f].rule.count_u) << s;
            EXPECT_EQ(r[f].rule.g1, base[f].rule.g1) << s;
            EXPECT_NEAR(r[f].error.ratio(), base[f].error.ratio(), 1e-6) << s;
            EXPECT_NEAR(r[f].tolerance, s * base[f].tolerance, 1e-9 * s * base[f].tolerance);
        }
    }
}

}  // namespace
}  // namespace trimkit::fit

namespace trimkit::fit {
namespace {

// The middle face of the G1 strip with its surface damaged (an interior control
// point pushed 0.5 up: a bump over the 2 x 4 face that tilts its normals along the
// edges by a few degrees): compression keeps it (the fit follows the edges, not the
// bump); rebuild judges G1 within 10° and replaces the face from its edges and G1
// neighbours, which gives back the undamaged surface within 1 % and G1.
TEST(CompressModel, RebuildRepairsADamagedSurfaceFromItsEdgesAndNeighbours) {
    const geom::Model good = test::g1_strip();
    geom::Model damaged = good;
    const geom::NurbsSurface& S = good.faces[1].surface;
    std::vector<Eigen::Vector3d> P = S.points();
    P[3 * S.count_v() + 2].z() += 0.5;
    damaged.faces[1].surface = geom::NurbsSurface(S.degree_u(), S.degree_v(), S.knots_u(), S.knots_v(), S.count_u(),
                                                  S.count_v(), P);
    CompressOptions options;
    options.faces = {1};
    std::vector<FaceCompression> report;
    compress_model(damaged, options, &report);
    ASSERT_FALSE(report[1].compressed) << "the bump is beyond 1 %";
    options.rebuild = true;
    const CompressedModel c = compress_model(damaged, options, &report);
    ASSERT_TRUE(report[1].compressed) << report[1].reason;
    const geom::Model e = extend_model(c);
    const FitError repaired = rebuilt_error(good, e, 1);  // against the undamaged face
    const double angle = max_g1_angle(e, 1, report[1].rule);
    std::printf("rebuilt face: %s; against the undamaged surface max %.3g (ratio %.3f%%), G1 max %.3f deg\n",
                report[1].reason.c_str(), repaired.max(), 100 * repaired.ratio(), angle);
    EXPECT_LT(repaired.ratio(), 0.01);
    EXPECT_EQ(report[1].g1_edges, 3) << "the left edge and both pieces of the right";
    EXPECT_LT(angle, kG1MaxDegrees);
}

}  // namespace
}  // namespace trimkit::fit
