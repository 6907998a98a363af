#include <gtest/gtest.h>

#include <cmath>

#include "geom/analytic_surfaces.h"
#include "mesh/mesh.h"
#include "tess/surface_test_support.h"
#include "tess/tessellate_face.h"

namespace trimkit::tess {
namespace {

// Circle of n points around (cu, cv) starting at its top point (cu, cv + r).
TrimPolygon circle_from_top(const geom::NurbsSurface& S, double cu, double cv, double r, int n, bool outer) {
    TrimPolygon loop;
    loop.outer = outer;
    for (int k = 0; k < n; ++k) {
        const double a = M_PI / 2 + (outer ? 2.0 : -2.0) * M_PI * k / n;
        loop.points.push_back(test::on_surface(S, cu + r * std::cos(a), cv + r * std::sin(a)));
    }
    return loop;
}

// ec_turbine-A.stp face 1: a disc whose hole touches the outer circle at one point
// (both loops start there). The hole must still be cut out.
TEST(TouchingLoops, HoleTouchingTheOuterLoopAtAVertexIsCut) {
    const geom::NurbsSurface plane = geom::plane_patch(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(),
                                                       Eigen::Vector3d::UnitY(), -3, 3, -3, 3);
    const int n = 256;
    const std::vector<TrimPolygon> loops{circle_from_top(plane, 0, 0, 2, n, true),
                                         circle_from_top(plane, 0, 1, 1, n, false)};
    TessellationOptions options;
    options.tolerance = 0.01;
    const mesh::Mesh m = tessellate_face(test::face_of(plane), loops, options, 0);
    const double polygon_area = 0.5 * n * std::sin(2 * M_PI / n) * (4.0 - 1.0);
    // The hole is 3.14 of the 12.57. Bridged like a free hole, the ring was pinched at
    // the touching point twice and a folded triangle added 3e-5; spliced there, none.
    EXPECT_NEAR(mesh::surface_area(m), polygon_area, 1e-9);
    for (const auto& t : m.triangles) {
        const Eigen::Vector2d a = m.uvs[t[0]], b = m.uvs[t[1]], c = m.uvs[t[2]];
        EXPECT_GE((b - a).x() * (c - a).y() - (b - a).y() * (c - a).x(), 0.0) << "folded triangle";
    }
}

}  // namespace
}  // namespace trimkit::tess
