#include "tess/share_edge_points.h"

#include <gtest/gtest.h>

#include "geom/error.h"
#include "tess/approximate_trim_curve.h"
#include "tess/tess_test_cases.h"

namespace trimkit::tess {
namespace {

// Two faces of the unit box meeting along the edge x = z = 0 (y from 0 to 1):
// A the bottom z = 0 with S_A(u,v) = (u, v, 0), B the side x = 0 with
// S_B(u,v) = (0, 1 - u, v). A's loop runs the edge from (0,1) to (0,0) in uv
// (against the edge); B's coedge runs it with it, on a non-uniform quadratic
// parameterisation of its bottom line v = 0, from u = 1 to u = 0.
TEST(ShareEdgePoints, BoxFacesGetIdenticalEdgeVertices) {
    const geom::NurbsSurface SA = geom::plane_patch(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(),
                                                    Eigen::Vector3d::UnitY(), 0, 1, 0, 1);
    const geom::NurbsSurface SB = geom::plane_patch(Eigen::Vector3d(0, 1, 0), -Eigen::Vector3d::UnitY(),
                                                    Eigen::Vector3d::UnitZ(), 0, 1, 0, 1);
    TrimPolyline on_a;
    for (double v : {1.0, 0.8, 0.55, 0.5, 0.3, 0.1, 0.0}) {
        PolylinePoint p;
        p.uv = {0.0, v};
        p.t = 1.0 - v;
        p.xyz = SA.evaluate(0.0, v);
        on_a.points.push_back(p);
    }
    geom::Coedge b;
    b.curve = geom::NurbsCurve2d(2, {0, 0, 0, 1, 1, 1}, {{1, 0}, {0.9, 0}, {0, 0}});
    b.edge = 7;
    b.edge_reversed = false;

    const SharedEdgePolyline shared = share_edge_points(SB, b, edge_points_from(on_a, true));
    const auto& P = shared.polyline.points;
    ASSERT_EQ(P.size(), on_a.points.size());
    EXPECT_EQ(shared.polyline.edge, 7);
    EXPECT_LT(shared.max_gap, 1e-14);
    for (size_t i = 0; i < P.size(); ++i) {
        const PolylinePoint& a = on_a.points[P.size() - 1 - i];  // opposite traversal
        EXPECT_EQ(P[i].xyz, a.xyz) << i;                        // bit-identical
        EXPECT_LT((P[i].uv - b.curve.evaluate(P[i].t)).norm(), 1e-15);  // on B's trim curve
        EXPECT_NEAR(P[i].uv.y(), 0.0, 1e-15);                          // B's edge v = 0
        EXPECT_LT((SB.evaluate(P[i].uv.x(), P[i].uv.y()) - a.xyz).norm(), 1e-13);
        if (i > 0) {
            EXPECT_GT(P[i].t, P[i - 1].t);
        }
    }
    EXPECT_EQ(P.front().t, 0.0);
    EXPECT_EQ(P.back().t, 1.0);

    // A file gap: B moved 1e-4 off the edge is reported, the points stay A's.
    const geom::NurbsSurface SB_off = SB.transformed(Eigen::Affine3d(Eigen::Translation3d(1e-4, 0, 0)));
    const SharedEdgePolyline off = share_edge_points(SB_off, b, edge_points_from(on_a, true));
    EXPECT_NEAR(off.max_gap, 1e-4, 1e-12);
    EXPECT_EQ(off.polyline.points[3].xyz, on_a.points[3].xyz);
}

// A curved edge: the bottom circle of a cylinder, approximated on the cylinder,
// shared with a planar cap whose trim is a rational circle parameterised from
// another start angle.
TEST(ShareEdgePoints, CircleEdgeBetweenCylinderAndCap) {
    const geom::NurbsSurface cyl = geom::cylinder_patch(
        Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ(), Eigen::Vector3d::UnitX(), 1.0, 0.0,
        2 * test::kPi, 0.0, 1.0);
    const geom::NurbsCurve2d bottom =
        geom::line_segment(Eigen::Vector2d(0, 0), Eigen::Vector2d(2 * test::kPi, 0));
    const TrimPolyline on_cyl = approximate_trim_curve(cyl, bottom, 1e-4, TrimMethod::kBezier3d);
    ASSERT_GT(on_cyl.points.size(), 20u);

    const geom::NurbsSurface cap = geom::plane_patch(Eigen::Vector3d(-2, -2, 0), Eigen::Vector3d(4, 0, 0),
                                                     Eigen::Vector3d(0, 4, 0), 0, 1, 0, 1);
    geom::Coedge c;  // the circle in the cap's uv: centre (0.5, 0.5), radius 0.25, CCW from angle 0
    c.curve = geom::to_2d(geom::circular_arc(Eigen::Vector3d(0.5, 0.5, 0), Eigen::Vector3d::UnitX(),
                                             Eigen::Vector3d::UnitY(), 0.25, 0.0, 2 * test::kPi));
    c.edge_reversed = false;  // same direction as the cylinder's coedge (edge direction)
    const SharedEdgePolyline shared = share_edge_points(cap, c, edge_points_from(on_cyl, false));
    ASSERT_EQ(shared.polyline.points.size(), on_cyl.points.size());
    EXPECT_LT(shared.max_gap, 1e-12);
    for (size_t i = 0; i < on_cyl.points.size(); ++i) {
        const PolylinePoint& p = shared.polyline.points[i];
        EXPECT_EQ(p.xyz, on_cyl.points[i].xyz);
        EXPECT_NEAR((p.uv - Eigen::Vector2d(0.5, 0.5)).norm(), 0.25, 1e-12);
        if (i > 0) {
            EXPECT_GE(p.t, shared.polyline.points[i - 1].t);
        }
    }
}

TEST(ShareEdgePoints, RejectsFewerThanTwoPoints) {
    geom::Coedge c;
    c.curve = geom::line_segment(Eigen::Vector2d(0, 0), Eigen::Vector2d(1, 0));
    EXPECT_THROW(share_edge_points(test::skewed_bilinear(), c, {Eigen::Vector3d::Zero()}),
                 geom::InvalidInput);
}

}  // namespace
}  // namespace trimkit::tess
