// TessellationOptions::face_timeout (issue 13): a face that takes longer than the
// limit is stopped cooperatively and reported in failed_faces with defect "timeout"
// and its time; the model's other faces are still meshed.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "geom/analytic_curves.h"
#include "geom/analytic_surfaces.h"
#include "geom/error.h"
#include "tess/tessellate_model.h"

namespace trimkit::tess {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A unit square face of the plane z = 0 at x offset x0, bounded by its natural boundary.
geom::Face square(double x0) {
    geom::Face face;
    face.surface = geom::plane_patch({x0, 0, 0}, Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), 0, 1, 0, 1);
    face.surface_kind = "plane";
    face.loops = {geom::natural_boundary_loop(face.surface)};
    return face;
}

// A face of the unit square trimmed by the star polygon {n/k}: n points on a circle,
// each joined to the one k steps on. Each of its n sides crosses about 2k others,
// so the loop repair meets ~n k crossings (here 2.4 million): seconds of work.
geom::Face star(double x0, int n, int k) {
    geom::Face face = square(x0);
    geom::Loop loop;
    loop.outer = true;
    auto point = [&](int i) {
        const double a = 2.0 * kPi * ((static_cast<long long>(i) * k) % n) / n;
        return Eigen::Vector2d(0.5 + 0.45 * std::cos(a), 0.5 + 0.45 * std::sin(a));
    };
    for (int i = 0; i < n; ++i) {
        geom::Coedge coedge;
        coedge.curve = geom::line_segment(point(i), point(i + 1));
        loop.coedges.push_back(coedge);
    }
    face.loops = {loop};
    return face;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(FaceTimeout, CostlyFaceFailsWithTimeoutAndTheOthersAreMeshed) {
    geom::Model model;
    model.faces = {square(0.0), star(2.0, 2401, 1200), square(4.0)};
    model.free_faces = {0, 1, 2};
    TessellationOptions options;
    options.tolerance = 1e-3;
    options.threads = 1;
    options.face_timeout = 0.25;
    const auto start = std::chrono::steady_clock::now();
    const TessellationResult result = tessellate_model(model, options);
    const double seconds = seconds_since(start);

    ASSERT_EQ(result.failed_faces.size(), 1u);
    const FailedFace& failed = result.failed_faces[0];
    EXPECT_EQ(failed.face, 1);
    EXPECT_EQ(failed.defect, "timeout");
    EXPECT_NE(failed.reason.find("face 1: timeout: stopped after"), std::string::npos) << failed.reason;
    EXPECT_NE(failed.reason.find("(limit 0.25 s)"), std::string::npos) << failed.reason;
    EXPECT_GE(failed.seconds, options.face_timeout);
    // Stopped promptly (the checks read the clock every few hundred loop steps), not retried.
    EXPECT_LT(failed.seconds, options.face_timeout + 1.0);
    EXPECT_TRUE(std::isnan(failed.area_mesh));
    EXPECT_EQ(result.faces_meshed, 2);
    EXPECT_GT(result.mesh.triangle_count(), 0u);
    for (int id : result.mesh.face_ids) EXPECT_NE(id, 1);
    EXPECT_LT(seconds, 5.0);
}

TEST(FaceTimeout, SoundFacesAreUnaffectedByTheDefault) {
    geom::Model model;
    model.faces = {square(0.0), square(2.0)};
    model.free_faces = {0, 1};
    TessellationOptions options;
    EXPECT_EQ(options.face_timeout, kDefaultFaceTimeout);
    const TessellationResult result = tessellate_model(model, options);
    EXPECT_TRUE(result.failed_faces.empty());
    EXPECT_EQ(result.faces_meshed, 2);
}

TEST(FaceTimeout, NegativeOrNanIsInvalidZeroIsNoLimit) {
    TessellationOptions options;
    options.face_timeout = -1.0;
    EXPECT_THROW(validate(options), geom::InvalidInput);
    options.face_timeout = std::nan("");
    EXPECT_THROW(validate(options), geom::InvalidInput);
    options.face_timeout = 0.0;
    EXPECT_NO_THROW(validate(options));
}

}  // namespace
}  // namespace trimkit::tess
