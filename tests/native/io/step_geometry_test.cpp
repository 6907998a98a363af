// STEP geometry entities to NURBS: edge pieces of lines, circles and rational
// B-splines in both senses, every surface kind sized by a boundary (each boundary
// point found on the surface through Surface::map), B-spline surfaces against
// hand-computed points, malformed entities naming their #id, and a shared file.
#include "io/step_geometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "geom/error.h"
#include "io/boundary_extent.h"
#include "test_support.h"

namespace trimkit::io {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

constexpr double kPi = 3.14159265358979323846;
const double kS = std::sqrt(0.5);

std::string part21(const std::string& data) {
    return "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION((''),'2;1');\n"
           "FILE_NAME('t.stp','',(''),(''),'','','');\nFILE_SCHEMA(('AUTOMOTIVE_DESIGN'));\nENDSEC;\nDATA;\n" +
           data + "ENDSEC;\nEND-ISO-10303-21;\n";
}

StepPart21 parse(const std::string& data) { return StepPart21::parse(part21(data), "t.stp"); }

// A parsed text and its geometry (StepGeometry refers to its file).
struct Parsed {
    StepPart21 file;
    StepGeometry g;
    explicit Parsed(const std::string& data, double radians_per_angle = 1.0)
        : file(parse(data)), g(file, radians_per_angle) {}
};

// A placement #10 at `o` with axis #11 and ref_direction #12, and its point/directions.
std::string frame(const std::string& o, const std::string& z = "0.,0.,1.", const std::string& x = "1.,0.,0.") {
    return "#10=AXIS2_PLACEMENT_3D('',#13,#11,#12);\n#11=DIRECTION('',(" + z + "));\n#12=DIRECTION('',(" + x +
           "));\n#13=CARTESIAN_POINT('',(" + o + "));\n";
}

void expect_near(const Vector3d& a, const Vector3d& b, double tol) {
    EXPECT_LE((a - b).norm(), tol) << "got " << a.transpose() << ", expected " << b.transpose();
}

// Every point of `boundary` with its STEP parameters `st` lies on the surface.
void expect_on_surface(const StepGeometry::Surface& s, const std::vector<Vector3d>& boundary,
                       const std::vector<Vector2d>& st, double tol) {
    ASSERT_EQ(boundary.size(), st.size());
    for (std::size_t k = 0; k < boundary.size(); ++k) {
        const Vector2d uv = s.map.apply(st[k]);
        expect_near(s.nurbs.evaluate(uv.x(), uv.y()), boundary[k], tol);
        const auto [u0, u1] = s.nurbs.domain_u();
        const auto [v0, v1] = s.nurbs.domain_v();
        EXPECT_TRUE(uv.x() >= u0 - 1e-12 && uv.x() <= u1 + 1e-12 && uv.y() >= v0 - 1e-12 && uv.y() <= v1 + 1e-12)
            << "(s, t) = " << st[k].transpose() << " maps outside the domain";
    }
}

// ---- Placements -----------------------------------------------------------------------

TEST(StepGeometry, PlacementOrthonormalisesRefDirectionAndDefaultsPerIso) {
    const StepPart21 f = parse(frame("1.,2.,3.", "0.,0.,2.", "1.,0.,1.") +
                               "#20=AXIS2_PLACEMENT_3D('',#13,#21,$);\n#21=DIRECTION('',(1.,0.,0.));\n"
                               "#30=AXIS1_PLACEMENT('',#13,$);\n#40=CARTESIAN_POINT('',(4.,5.));\n");
    const StepGeometry g(f);
    const Eigen::Affine3d M = g.placement(10);
    expect_near(M.translation(), Vector3d(1, 2, 3), 0);
    expect_near(M.linear().col(0), Vector3d(1, 0, 0), 1e-15);  // (1,0,1) minus its z part
    expect_near(M.linear().col(1), Vector3d(0, 1, 0), 1e-15);
    expect_near(M.linear().col(2), Vector3d(0, 0, 1), 1e-15);
    // Axis (1,0,0) without ref_direction: ISO first_proj_axis takes (0,1,0).
    const Eigen::Affine3d N = g.placement(20);
    expect_near(N.linear().col(0), Vector3d(0, 1, 0), 1e-15);
    expect_near(N.linear().col(1), Vector3d(0, 0, 1), 1e-15);
    const Eigen::Affine3d A = g.placement(30);
    expect_near(A.linear().col(2), Vector3d(0, 0, 1), 0);
    expect_near(g.point(40), Vector3d(4, 5, 0), 0);
    expect_near(g.direction(11), Vector3d(0, 0, 1), 0);
}

// A ref_direction along the axis (ul_to252.step: axis -x, ref +x) is taken as unset,
// as OCCT's reader does: the frame ISO's first_proj_axis gives, not a lost face.
TEST(StepGeometry, RefDirectionAlongTheAxisIsTakenAsUnset) {
    const StepPart21 f = parse(frame("0.,0.,0.", "-1.,0.,0.", "1.,0.,0."));
    const StepGeometry g(f);
    const Eigen::Affine3d M = g.placement(10);
    expect_near(M.linear().col(2), Vector3d(-1, 0, 0), 0);
    expect_near(M.linear().col(0), Vector3d(0, 1, 0), 1e-15);  // axis along x: (0,1,0)
    expect_near(M.linear().col(1), Vector3d(0, 0, -1), 1e-15);  // z cross x
}

// ---- Curves ---------------------------------------------------------------------------

// Circle about (1,2,3) in the placement's XY plane, radius 2.
const std::string kCircle = frame("1.,2.,3.") + "#1=CIRCLE('',#10,2.);\n";

TEST(StepGeometry, CircleArcFollowsTheSense) {
    const Parsed parsed(kCircle);
    const StepGeometry& g = parsed.g;
    const Vector3d a(3, 2, 3), b(1, 4, 3);  // angles 0 and 90 degrees
    const geom::NurbsCurve3d ccw = g.edge_curve(1, a, b, true, 1e-9);
    const auto [c0, c1] = ccw.domain();
    expect_near(ccw.evaluate(c0), a, 1e-14);
    expect_near(ccw.evaluate(c1), b, 1e-14);
    // The middle of a one-segment arc's domain is its middle angle, 45 degrees.
    expect_near(ccw.evaluate(0.5 * (c0 + c1)), Vector3d(1 + std::sqrt(2.0), 2 + std::sqrt(2.0), 3), 1e-14);
    // Against the circle: from 0 down through 270 degrees to 90, the middle at -135.
    const geom::NurbsCurve3d cw = g.edge_curve(1, a, b, false, 1e-9);
    const auto [d0, d1] = cw.domain();
    expect_near(cw.evaluate(d0), a, 1e-14);
    expect_near(cw.evaluate(d1), b, 1e-14);
    expect_near(cw.evaluate(0.5 * (d0 + d1)), Vector3d(1 - std::sqrt(2.0), 2 - std::sqrt(2.0), 3), 1e-14);
    expect_near(cw.evaluate(d0 + (d1 - d0) / 3), Vector3d(1, 0, 3), 1e-14);  // 270 degrees
}

TEST(StepGeometry, WholeCircleWhenTheVerticesCoincide) {
    const Parsed parsed(kCircle);
    const StepGeometry& g = parsed.g;
    const Vector3d a(1, 4, 3);  // 90 degrees
    const geom::NurbsCurve3d c = g.edge_curve(1, a, a + Vector3d(1e-12, 0, 0), true, 1e-9);
    const auto [t0, t1] = c.domain();
    EXPECT_NEAR(t1 - t0, 2 * kPi, 1e-12);
    expect_near(c.evaluate(t0), a, 1e-14);
    expect_near(c.evaluate(t1), a, 1e-14);
    expect_near(c.evaluate(0.5 * (t0 + t1)), Vector3d(1, 0, 3), 1e-14);        // 270 degrees
    expect_near(c.evaluate(t0 + 0.25 * (t1 - t0)), Vector3d(-1, 2, 3), 1e-14);  // 180 degrees
    const geom::NurbsCurve3d r = g.edge_curve(1, a, a, false, 1e-9);
    expect_near(r.evaluate(r.domain().first + 0.25 * (r.domain().second - r.domain().first)), Vector3d(3, 2, 3),
                1e-14);  // clockwise: 0 degrees first
}

TEST(StepGeometry, LineSegmentBetweenItsVertices) {
    const Parsed parsed("#1=LINE('',#2,#3);\n#2=CARTESIAN_POINT('',(0.,1.,0.));\n"
                               "#3=VECTOR('',#4,2.);\n#4=DIRECTION('',(1.,0.,0.));\n");
    const StepGeometry& g = parsed.g;
    const geom::NurbsCurve3d c = g.edge_curve(1, Vector3d(2, 1, 0), Vector3d(6, 1, 0), true, 1e-9);
    EXPECT_DOUBLE_EQ(c.domain().first, 1.0);  // the line's parameter: 2 per unit
    EXPECT_DOUBLE_EQ(c.domain().second, 3.0);
    expect_near(c.evaluate(2.0), Vector3d(4, 1, 0), 1e-15);
    const geom::NurbsCurve3d r = g.edge_curve(1, Vector3d(6, 1, 0), Vector3d(2, 1, 0), false, 1e-9);
    expect_near(r.evaluate(r.domain().first), Vector3d(6, 1, 0), 1e-15);
    expect_near(r.evaluate(r.domain().second), Vector3d(2, 1, 0), 1e-15);
    EXPECT_THROW(g.edge_curve(1, Vector3d(2, 1, 0), Vector3d(2, 1, 0), true, 1e-9), geom::ReadError);
}

// A quarter of the unit circle as a rational quadratic (weights 1, √2/2, 1), complex form.
const std::string kRationalCurve =
    "#1=(BOUNDED_CURVE()B_SPLINE_CURVE(2,(#2,#3,#4),.CIRCULAR_ARC.,.F.,.F.)"
    "B_SPLINE_CURVE_WITH_KNOTS((3,3),(0.,1.),.PIECEWISE_BEZIER_KNOTS.)CURVE()GEOMETRIC_REPRESENTATION_ITEM()"
    "RATIONAL_B_SPLINE_CURVE((1.,0.707106781186547524,1.))REPRESENTATION_ITEM(''));\n"
    "#2=CARTESIAN_POINT('',(1.,0.,0.));\n#3=CARTESIAN_POINT('',(1.,1.,0.));\n#4=CARTESIAN_POINT('',(0.,1.,0.));\n";

TEST(StepGeometry, RationalBSplineCurveFromComplexInstance) {
    const Parsed parsed(kRationalCurve);
    const StepGeometry& g = parsed.g;
    const geom::NurbsCurve3d c = g.edge_curve(1, Vector3d(1, 0, 0), Vector3d(0, 1, 0), true, 1e-9);
    ASSERT_TRUE(c.is_rational());
    // t = 1/2: Bernstein 1/4, 1/2, 1/4; x = (1/4 + (1/2)(√2/2)) / (1/2 + (1/2)(√2/2)) = √2/2.
    expect_near(c.evaluate(0.5), Vector3d(kS, kS, 0), 1e-15);
    // The piece from 45 degrees back to 0 against the curve.
    const geom::NurbsCurve3d r = g.edge_curve(1, Vector3d(kS, kS, 0), Vector3d(1, 0, 0), false, 1e-9);
    expect_near(r.evaluate(r.domain().first), Vector3d(kS, kS, 0), 1e-12);
    expect_near(r.evaluate(r.domain().second), Vector3d(1, 0, 0), 1e-12);
}

TEST(StepGeometry, ClosedBSplineFromAVertexInsideItsDomain) {
    // A closed degree-1 loop round the unit square; the vertex (1,1,0) is at t = 2.
    const Parsed parsed("#1=B_SPLINE_CURVE_WITH_KNOTS('',1,(#2,#3,#4,#5,#2),.POLYLINE_FORM.,.T.,.F.,"
                               "(2,1,1,1,2),(0.,1.,2.,3.,4.),.UNSPECIFIED.);\n#2=CARTESIAN_POINT('',(0.,0.,0.));\n"
                               "#3=CARTESIAN_POINT('',(1.,0.,0.));\n#4=CARTESIAN_POINT('',(1.,1.,0.));\n"
                               "#5=CARTESIAN_POINT('',(0.,1.,0.));\n");
    const StepGeometry& g = parsed.g;
    const Vector3d v(1, 1, 0);
    const geom::NurbsCurve3d c = g.edge_curve(1, v, v, true, 1e-9);
    const auto [t0, t1] = c.domain();
    EXPECT_DOUBLE_EQ(t1 - t0, 4.0);
    expect_near(c.evaluate(t0), v, 1e-15);
    expect_near(c.evaluate(t0 + 1), Vector3d(0, 1, 0), 1e-15);
    expect_near(c.evaluate(t0 + 2), Vector3d(0, 0, 0), 1e-15);
    expect_near(c.evaluate(t1), v, 1e-15);
    // Across the closure from (0,1,0) to (1,0,0): through (0,0,0).
    const geom::NurbsCurve3d p = g.edge_curve(1, Vector3d(0, 1, 0), Vector3d(1, 0, 0), true, 1e-9);
    expect_near(p.evaluate(p.domain().first), Vector3d(0, 1, 0), 1e-15);
    expect_near(p.evaluate(0.5 * (p.domain().first + p.domain().second)), Vector3d(0, 0, 0), 1e-15);
    expect_near(p.evaluate(p.domain().second), Vector3d(1, 0, 0), 1e-15);
}

TEST(StepGeometry, SurfaceCurveAndTrimmedCurveUseTheirCurve) {
    const Parsed parsed(kCircle + "#2=SURFACE_CURVE('',#3,(#99),.CURVE_3D.);\n"
                                         "#3=TRIMMED_CURVE('',#1,(PARAMETER_VALUE(0.)),(PARAMETER_VALUE(1.)),.T.,"
                                         ".PARAMETER.);\n#4=PCURVE('',#99,#98);\n#5=OFFSET_CURVE_3D('',#1,1.,.F.,#11);\n");
    const StepGeometry& g = parsed.g;
    const geom::NurbsCurve3d c = g.edge_curve(2, Vector3d(3, 2, 3), Vector3d(1, 4, 3), true, 1e-9);
    expect_near(c.evaluate(c.domain().second), Vector3d(1, 4, 3), 1e-14);
    EXPECT_THROW(g.edge_curve(4, Vector3d(3, 2, 3), Vector3d(1, 4, 3), true, 1e-9), UnsupportedStepEntity);
    EXPECT_THROW(g.edge_curve(5, Vector3d(3, 2, 3), Vector3d(1, 4, 3), true, 1e-9), UnsupportedStepEntity);
}

// ---- Elementary surfaces ------------------------------------------------------------

// Points along a circle about the z axis: radius r at height z, angles a0 .. a1, n steps.
std::vector<Vector3d> arc_points(double r, double z, double a0, double a1, int n, const Vector3d& c = Vector3d::Zero()) {
    std::vector<Vector3d> p;
    for (int k = 0; k <= n; ++k) {
        const double a = a0 + (a1 - a0) * k / n;
        p.push_back(c + Vector3d(r * std::cos(a), r * std::sin(a), z));
    }
    return p;
}

TEST(StepGeometry, PlaneCoversTheBoundarySquare) {
    const Parsed parsed(frame("0.,0.,5.") + "#1=PLANE('',#10);\n");
    const StepGeometry& g = parsed.g;
    std::vector<Vector3d> b;
    const Vector3d corners[] = {{1, 1, 5}, {3, 1, 5}, {3, 4, 5}, {1, 4, 5}};
    for (int e = 0; e < 4; ++e)
        for (int k = 0; k < 16; ++k) b.push_back(corners[e] + (corners[(e + 1) % 4] - corners[e]) * k / 16.0);
    const StepGeometry::Surface s = g.surface(1, b);
    EXPECT_EQ(s.kind, "plane");
    // u over [1, 3], v over [1, 4], each widened by 2% of its length.
    EXPECT_NEAR(s.nurbs.domain_u().first, 1 - 0.04, 1e-14);
    EXPECT_NEAR(s.nurbs.domain_u().second, 3 + 0.04, 1e-14);
    EXPECT_NEAR(s.nurbs.domain_v().first, 1 - 0.06, 1e-14);
    EXPECT_NEAR(s.nurbs.domain_v().second, 4 + 0.06, 1e-14);
    expect_near(s.nurbs.evaluate(0.96, 0.94), Vector3d(0.96, 0.94, 5), 1e-14);
    expect_near(s.nurbs.evaluate(3.04, 4.06), Vector3d(3.04, 4.06, 5), 1e-14);
    std::vector<Vector2d> st;
    for (const Vector3d& p : b) st.emplace_back(p.x(), p.y());
    expect_on_surface(s, b, st, 1e-14);
    EXPECT_THROW(g.surface(1, {}), geom::ReadError);
}

TEST(StepGeometry, CylinderWithAFullTurnBoundary) {
    // Axis along y through (1,0,0); ref_direction z, so angle 0 points along +z.
    const Parsed parsed(frame("1.,0.,0.", "0.,1.,0.", "0.,0.,1.") + "#1=CYLINDRICAL_SURFACE('',#10,2.);\n");
    const StepGeometry& g = parsed.g;
    // Frame: X = z, Y = Z × X = y × z = x. A point at angle a, height h: (1,0,0) + h y + 2 (cos a z + sin a x).
    auto at = [](double a, double h) { return Vector3d(1 + 2 * std::sin(a), h, 2 * std::cos(a)); };
    std::vector<Vector3d> b;
    std::vector<Vector2d> st;
    for (double h : {1.0, 3.0})
        for (int k = 0; k <= 16; ++k) {
            const double a = 2 * kPi * k / 16;
            b.push_back(at(a, h));
            st.emplace_back(a, h);
        }
    const StepGeometry::Surface s = g.surface(1, b);
    EXPECT_EQ(s.kind, "cylinder");
    ASSERT_TRUE(s.map.u.arc.has_value());
    EXPECT_EQ(s.map.u.arc->theta0(), 0.0);
    EXPECT_NEAR(s.map.u.arc->theta1(), 2 * kPi, 1e-15);
    EXPECT_NEAR(s.nurbs.domain_v().first, 1 - 0.04, 1e-14);
    EXPECT_NEAR(s.nurbs.domain_v().second, 3 + 0.04, 1e-14);
    expect_on_surface(s, b, st, 1e-9);
}

TEST(StepGeometry, CylinderPartialTurnAcrossAngleZeroGetsTheWholeTurn) {
    const Parsed parsed(frame("0.,0.,0.") + "#1=CYLINDRICAL_SURFACE('',#10,1.);\n");
    const StepGeometry& g = parsed.g;
    // A face from -30 to +60 degrees: arcs and two rulings.
    const double a0 = -kPi / 6, a1 = kPi / 3;
    std::vector<Vector3d> b = arc_points(1, 0, a0, a1, 16);
    for (const Vector3d& p : arc_points(1, 2, a1, a0, 16)) b.push_back(p);
    const StepGeometry::Surface s = g.surface(1, b);
    // Periodic directions get the whole turn [0, 2pi] (the loops across the seam are
    // face_loops' to unwrap): the boundary's points cannot tell which side is the face.
    EXPECT_EQ(s.map.u.arc->theta0(), 0.0);
    EXPECT_NEAR(s.map.u.arc->theta1(), 2 * kPi, 1e-15);
    std::vector<Vector2d> st;
    for (const Vector3d& p : b) {
        double a = std::atan2(p.y(), p.x());
        if (a < s.map.u.arc->theta0()) a += 2 * kPi;
        st.emplace_back(a, p.z());
    }
    expect_on_surface(s, b, st, 1e-12);
}

TEST(StepGeometry, ConeSemiAngleInDegrees) {
    // Radius 1 at the location, semi-angle 45 degrees: r(v) = 1 + v.
    const Parsed parsed(frame("0.,0.,0.") + "#1=CONICAL_SURFACE('',#10,1.,45.);\n", kPi / 180);
    const StepGeometry& g = parsed.g;
    std::vector<Vector3d> b = arc_points(1, 0, 0, kPi / 2, 16);
    for (const Vector3d& p : arc_points(3, 2, kPi / 2, 0, 16)) b.push_back(p);
    const StepGeometry::Surface s = g.surface(1, b);
    EXPECT_EQ(s.kind, "cone");
    EXPECT_EQ(s.map.u.arc->theta0(), 0.0);
    EXPECT_NEAR(s.map.u.arc->theta1(), 2 * kPi, 1e-15);
    EXPECT_NEAR(s.nurbs.domain_v().first, -0.04, 1e-14);
    EXPECT_NEAR(s.nurbs.domain_v().second, 2.04, 1e-14);
    const Vector2d uv = s.map.apply(Vector2d(0, 2));
    expect_near(s.nurbs.evaluate(uv.x(), uv.y()), Vector3d(3, 0, 2), 1e-14);
    std::vector<Vector2d> st;
    for (const Vector3d& p : b) st.emplace_back(std::atan2(p.y(), p.x()), p.z());
    expect_on_surface(s, b, st, 1e-12);
}

TEST(StepGeometry, ConeCapReachesTheApexButNotPast) {
    const Parsed parsed(frame("0.,0.,0.") + "#1=CONICAL_SURFACE('',#10,1.,0.785398163397448310);\n");
    const StepGeometry& g = parsed.g;
    // One full circle of radius 2 at height 1: a cap whose apex is at v = -1.
    const StepGeometry::Surface s = g.surface(1, arc_points(2, 1, 0, 2 * kPi, 16));
    EXPECT_EQ(s.map.u.arc->theta1() - s.map.u.arc->theta0(), 2 * kPi);
    EXPECT_NEAR(s.nurbs.domain_v().first, -1, 1e-15);
    EXPECT_NEAR(s.nurbs.domain_v().second, 1, 1e-9);
    expect_near(s.nurbs.evaluate(1.0, -1), Vector3d(0, 0, -1), 1e-15);
    // A band starting exactly at the apex stays on its nappe.
    std::vector<Vector3d> band = arc_points(1e-300, -1, 0, 2 * kPi, 4);
    for (const Vector3d& p : arc_points(2, 1, 0, 2 * kPi, 16)) band.push_back(p);
    EXPECT_NEAR(g.surface(1, band).nurbs.domain_v().first, -1, 1e-15);
}

TEST(StepGeometry, SphereOctantUpToThePole) {
    const Parsed parsed(frame("1.,1.,1.") + "#1=SPHERICAL_SURFACE('',#10,2.);\n");
    const StepGeometry& g = parsed.g;
    const Vector3d c(1, 1, 1);
    auto at = [&](double th, double ph) -> Vector3d {
        return c + 2 * Vector3d(std::cos(ph) * std::cos(th), std::cos(ph) * std::sin(th), std::sin(ph));
    };
    std::vector<Vector3d> b;
    std::vector<Vector2d> st;
    for (int k = 0; k < 16; ++k) st.emplace_back(kPi / 2 * k / 16, 0);           // equator
    for (int k = 0; k < 16; ++k) st.emplace_back(kPi / 2, kPi / 2 * k / 16);    // meridian up
    for (int k = 16; k > 0; --k) st.emplace_back(0, kPi / 2 * k / 16);          // meridian down (pole first)
    for (const Vector2d& x : st) b.push_back(at(x.x(), x.y()));
    const StepGeometry::Surface s = g.surface(1, b);
    EXPECT_EQ(s.kind, "sphere");
    // The whole sphere: an octant's boundary and the rest of the sphere less an
    // octant have the same points.
    EXPECT_EQ(s.map.u.arc->theta0(), 0.0);
    EXPECT_NEAR(s.map.u.arc->theta1(), 2 * kPi, 1e-15);
    EXPECT_EQ(s.map.v.arc->theta0(), -kPi / 2);
    EXPECT_EQ(s.map.v.arc->theta1(), kPi / 2);  // not past the pole
    expect_near(s.nurbs.evaluate(s.nurbs.domain_u().first, s.nurbs.domain_v().second), Vector3d(1, 1, 3), 1e-14);
    st[32] = Vector2d(kPi / 4, kPi / 2);  // the pole has any longitude
    expect_on_surface(s, b, st, 1e-12);
    // Going all the way round (a cap or a band, the boundary cannot tell): pole to pole.
    const StepGeometry::Surface whole = g.surface(1, arc_points(2, 1, 0, 2 * kPi, 16, Vector3d(1, 1, 0)));
    EXPECT_EQ(whole.map.v.arc->theta0(), -kPi / 2);
    EXPECT_EQ(whole.map.v.arc->theta1(), kPi / 2);
}

TEST(StepGeometry, TorusRingOfAQuarterTube) {
    // Major radius 5, minor 1 about z through the origin: a fillet from the outer
    // equator (φ = 0) up to the top (φ = π/2), all the way round, with its seam.
    const Parsed parsed(frame("0.,0.,0.") + "#1=TOROIDAL_SURFACE('',#10,5.,1.);\n");
    const StepGeometry& g = parsed.g;
    auto at = [](double th, double ph) {
        return Vector3d((5 + std::cos(ph)) * std::cos(th), (5 + std::cos(ph)) * std::sin(th), std::sin(ph));
    };
    std::vector<Vector2d> st;
    for (int k = 0; k <= 16; ++k) st.emplace_back(2 * kPi * k / 16, 0);
    for (int k = 0; k <= 16; ++k) st.emplace_back(0, kPi / 2 * k / 16);
    for (int k = 0; k <= 16; ++k) st.emplace_back(2 * kPi * (16 - k) / 16, kPi / 2);
    std::vector<Vector3d> b;
    for (const Vector2d& x : st) b.push_back(at(x.x(), x.y()));
    const StepGeometry::Surface s = g.surface(1, b);
    EXPECT_EQ(s.kind, "torus");
    EXPECT_EQ(s.map.u.arc->theta0(), 0.0);
    EXPECT_NEAR(s.map.u.arc->theta1(), 2 * kPi, 1e-15);
    EXPECT_EQ(s.map.v.arc->theta0(), 0.0);  // the whole tube
    EXPECT_NEAR(s.map.v.arc->theta1(), 2 * kPi, 1e-15);
    expect_on_surface(s, b, st, 1e-12);
}

TEST(StepGeometry, SpindleTorusPointsAcrossTheAxis) {
    // R = 1 < r = 2: where R + r cos φ < 0 (120 < φ < 240 degrees) a point of
    // parameter θ lies across the axis, at longitude θ + π.
    auto at = [](double th, double ph) {
        const double rho = 1 + 2 * std::cos(ph);
        return Vector3d(rho * std::cos(th), rho * std::sin(th), 2 * std::sin(ph));
    };
    std::vector<Vector2d> inner, outer;  // (θ, φ) round a patch's border
    for (int k = 0; k < 16; ++k) inner.emplace_back(kPi / 2 * k / 16, 5 * kPi / 6);
    for (int k = 0; k < 16; ++k) inner.emplace_back(kPi / 2, 5 * kPi / 6 + kPi / 3 * k / 16);
    for (int k = 0; k < 16; ++k) inner.emplace_back(kPi / 2 * (16 - k) / 16, 7 * kPi / 6);
    for (int k = 0; k <= 16; ++k) inner.emplace_back(0, 7 * kPi / 6 - kPi / 3 * k / 16);
    for (const Vector2d& x : inner) outer.emplace_back(x.x(), x.y() - kPi);  // φ from -30 to 30 degrees
    for (const char* surface : {"TOROIDAL_SURFACE('',#10,1.,2.)", "DEGENERATE_TOROIDAL_SURFACE('',#10,1.,2.,.F.)",
                                "DEGENERATE_TOROIDAL_SURFACE('',#10,1.,2.,.T.)"}) {
        const Parsed parsed(frame("0.,0.,0.") + "#1=" + surface + ";\n");
        const bool outer_part = std::string(surface).find(".T.") != std::string::npos;
        const std::vector<Vector2d>& st = outer_part ? outer : inner;
        std::vector<Vector3d> b;
        for (const Vector2d& x : st) b.push_back(at(x.x(), x.y()));
        const StepGeometry::Surface s = parsed.g.surface(1, b);
        EXPECT_EQ(s.map.u.arc->theta0(), 0.0) << surface;
        EXPECT_NEAR(s.map.u.arc->theta1(), 2 * kPi, 1e-15) << surface;
        expect_on_surface(s, b, st, 1e-12);
    }
}

TEST(StepGeometry, OffsetOfACylinderGrowsItsRadius) {
    const Parsed parsed(frame("0.,0.,0.") + "#1=CYLINDRICAL_SURFACE('',#10,2.);\n"
                                                   "#2=OFFSET_SURFACE('',#1,0.5,.F.);\n");
    const StepGeometry& g = parsed.g;
    std::vector<Vector3d> b = arc_points(2.5, 0, 0, 2 * kPi, 16);
    for (const Vector3d& p : arc_points(2.5, 1, 0, 2 * kPi, 16)) b.push_back(p);
    const StepGeometry::Surface s = g.surface(2, b);
    EXPECT_EQ(s.kind, "offset");
    expect_near(s.nurbs.evaluate(0, 0.5), Vector3d(2.5, 0, 0.5), 1e-14);
}

// ---- B-spline surfaces ----------------------------------------------------------------

TEST(StepGeometry, BilinearBSplineSurfaceRowsRunAlongU) {
    // Rows (outer list) are u: P00=(0,0,0) P01=(0,1,0) / P10=(2,0,0) P11=(2,1,1).
    const StepPart21 f = parse(
        "#1=B_SPLINE_SURFACE_WITH_KNOTS('',1,1,((#2,#3),(#4,#5)),.UNSPECIFIED.,.F.,.F.,.F.,(2,2),(2,2),(0.,1.),"
        "(0.,2.),.UNSPECIFIED.);\n#2=CARTESIAN_POINT('',(0.,0.,0.));\n#3=CARTESIAN_POINT('',(0.,1.,0.));\n"
        "#4=CARTESIAN_POINT('',(2.,0.,0.));\n#5=CARTESIAN_POINT('',(2.,1.,1.));\n"
        "#6=B_SPLINE_SURFACE_WITH_KNOTS('',1,1,((#2,#3),(#4,#5)),.UNSPECIFIED.,.F.,.F.,.F.,(2),(2),(0.),(1.),"
        ".UNSPECIFIED.);\n");
    const StepGeometry h(f);
    try {
        h.surface(6, {});
        ADD_FAILURE() << "no ReadError";
    } catch (const geom::ReadError& e) {  // one knot of multiplicity 2 each way
        EXPECT_NE(e.reason().find("#6 B_SPLINE_SURFACE_WITH_KNOTS: u_multiplicities sum to 2, expected 4"),
                  std::string::npos) << e.what();
    }
    const StepGeometry::Surface s = h.surface(1, {});
    EXPECT_EQ(s.kind, "bspline");
    EXPECT_TRUE(s.map.identity());
    expect_near(s.nurbs.evaluate(1, 0), Vector3d(2, 0, 0), 1e-15);  // P10: u = 1, v = 0
    expect_near(s.nurbs.evaluate(0, 2), Vector3d(0, 1, 0), 1e-15);  // P01
    // (u, v) = (1/2, 1): bilinear weights 1/4 each: (1, 1/2, 1/4).
    expect_near(s.nurbs.evaluate(0.5, 1), Vector3d(1, 0.5, 0.25), 1e-15);
}

TEST(StepGeometry, BicubicBezierSurfaceOnAParaboloidGrid) {
    // z = x² + y² over [0,1]²: its Bézier net is x_i = i/3, y_j = j/3,
    // z_ij = (i (i-1)/2... derived: x² has Bézier coefficients 0, 0, 1/3, 1 on degree 3.
    std::string data = "#1=BEZIER_SURFACE('',3,3,(";
    const double c[4] = {0, 0, 1.0 / 3, 1};
    int id = 100;
    std::string points;
    for (int i = 0; i < 4; ++i) {
        data += i ? ",(" : "(";
        for (int j = 0; j < 4; ++j) {
            data += (j ? ",#" : "#") + std::to_string(id);
            char buf[160];
            std::snprintf(buf, sizeof buf, "#%d=CARTESIAN_POINT('',(%.17g,%.17g,%.17g));\n", id, i / 3.0, j / 3.0,
                          c[i] + c[j]);
            points += buf;
            ++id;
        }
        data += ")";
    }
    data += "),.UNSPECIFIED.,.F.,.F.,.F.);\n" + points;
    const Parsed parsed(data);
    const StepGeometry& g = parsed.g;
    const StepGeometry::Surface s = g.surface(1, {});
    EXPECT_EQ(s.kind, "bezier");
    expect_near(s.nurbs.evaluate(0.3, 0.6), Vector3d(0.3, 0.6, 0.09 + 0.36), 1e-15);
}

TEST(StepGeometry, RationalBSplineSurfaceFromComplexInstance) {
    // A quarter cylinder: u the rational quarter circle of radius 1, v a line 0 -> 2 in z.
    std::string data =
        "#1=(BOUNDED_SURFACE()B_SPLINE_SURFACE(2,1,((#2,#3),(#4,#5),(#6,#7)),.UNSPECIFIED.,.F.,.F.,.F.)"
        "B_SPLINE_SURFACE_WITH_KNOTS((3,3),(2,2),(0.,1.),(0.,1.),.UNSPECIFIED.)GEOMETRIC_REPRESENTATION_ITEM()"
        "RATIONAL_B_SPLINE_SURFACE(((1.,1.),(0.707106781186547524,0.707106781186547524),(1.,1.)))"
        "REPRESENTATION_ITEM('')SURFACE());\n"
        "#2=CARTESIAN_POINT('',(1.,0.,0.));\n#3=CARTESIAN_POINT('',(1.,0.,2.));\n"
        "#4=CARTESIAN_POINT('',(1.,1.,0.));\n#5=CARTESIAN_POINT('',(1.,1.,2.));\n"
        "#6=CARTESIAN_POINT('',(0.,1.,0.));\n#7=CARTESIAN_POINT('',(0.,1.,2.));\n";
    const Parsed parsed(data);
    const StepGeometry& g = parsed.g;
    const StepGeometry::Surface s = g.surface(1, {});
    EXPECT_EQ(s.kind, "bspline");
    ASSERT_TRUE(s.nurbs.is_rational());
    expect_near(s.nurbs.evaluate(0.5, 0.5), Vector3d(kS, kS, 1), 1e-15);
    expect_near(s.nurbs.evaluate(1, 1), Vector3d(0, 1, 2), 1e-15);
}

// ---- Swept surfaces ---------------------------------------------------------------------

TEST(StepGeometry, ExtrusionOfACircle) {
    // The unit circle in z = 0 swept along (0,0,2): S(θ, v) = (cos θ, sin θ, 2v).
    const Parsed parsed(frame("0.,0.,0.") + "#1=CIRCLE('',#10,1.);\n#2=VECTOR('',#11,2.);\n"
                                                   "#3=SURFACE_OF_LINEAR_EXTRUSION('',#1,#2);\n");
    const StepGeometry& g = parsed.g;
    std::vector<Vector3d> b = arc_points(1, 0, 0, kPi, 16);
    for (const Vector3d& p : arc_points(1, 4, kPi, 0, 16)) b.push_back(p);
    const StepGeometry::Surface s = g.surface(3, b);
    EXPECT_EQ(s.kind, "extrusion");
    EXPECT_NEAR(s.nurbs.domain_v().first, -0.04, 1e-12);
    EXPECT_NEAR(s.nurbs.domain_v().second, 2.04, 1e-12);
    EXPECT_EQ(s.map.u.arc->theta0(), 0.0);  // the whole circle
    EXPECT_NEAR(s.map.u.arc->theta1(), 2 * kPi, 1e-15);
    std::vector<Vector2d> st;
    for (const Vector3d& p : b) st.emplace_back(std::atan2(p.y(), p.x()) < -1 ? kPi : std::atan2(p.y(), p.x()), p.z() / 2);
    expect_on_surface(s, b, st, 1e-12);
}

TEST(StepGeometry, RevolutionOfASlantedLine) {
    // The line (1,0,0) + t (1,0,1)/√2 turned about z: a cone; a quarter turn of t ∈ [0, 2].
    const Parsed parsed("#1=LINE('',#2,#3);\n#2=CARTESIAN_POINT('',(1.,0.,0.));\n#3=VECTOR('',#4,1.);\n"
                               "#4=DIRECTION('',(1.,0.,1.));\n#5=AXIS1_PLACEMENT('',#6,#7);\n"
                               "#6=CARTESIAN_POINT('',(0.,0.,0.));\n#7=DIRECTION('',(0.,0.,1.));\n"
                               "#8=SURFACE_OF_REVOLUTION('',#1,#5);\n");
    const StepGeometry& g = parsed.g;
    auto at = [](double th, double t) {
        const double r = 1 + t * kS;
        return Vector3d(r * std::cos(th), r * std::sin(th), t * kS);
    };
    std::vector<Vector2d> st;  // STEP: (angle, curve parameter)
    for (int k = 0; k <= 16; ++k) st.emplace_back(kPi / 2 * k / 16, 0);
    for (int k = 0; k <= 16; ++k) st.emplace_back(kPi / 2, 2.0 * k / 16);
    for (int k = 0; k <= 16; ++k) st.emplace_back(kPi / 2 * (16 - k) / 16, 2);
    for (int k = 0; k <= 16; ++k) st.emplace_back(0, 2.0 * (16 - k) / 16);
    std::vector<Vector3d> b;
    for (const Vector2d& x : st) b.push_back(at(x.x(), x.y()));
    const StepGeometry::Surface s = g.surface(8, b);
    EXPECT_EQ(s.kind, "revolution");
    EXPECT_TRUE(s.map.swap);
    EXPECT_NEAR(s.nurbs.domain_u().first, -0.04, 1e-12);
    EXPECT_NEAR(s.nurbs.domain_u().second, 2.04, 1e-12);
    EXPECT_EQ(s.map.v.arc->theta0(), 0.0);  // the whole turn
    EXPECT_NEAR(s.map.v.arc->theta1(), 2 * kPi, 1e-15);
    expect_on_surface(s, b, st, 1e-12);
}

TEST(StepGeometry, RevolutionOfAnArcTakesTheWholeGeneratrixCircle) {
    // A circle of radius 1 about (3,0,0) in the xz plane, turned about z: a torus of
    // major radius 3. Its generatrix angle 0 points along +x; the face covers the
    // inner half of the tube (generatrix angles 90..270 degrees) for a quarter turn.
    const Parsed parsed(frame("3.,0.,0.", "0.,-1.,0.", "1.,0.,0.") + "#1=CIRCLE('',#10,1.);\n"
                               "#5=AXIS1_PLACEMENT('',#6,#7);\n#6=CARTESIAN_POINT('',(0.,0.,0.));\n"
                               "#7=DIRECTION('',(0.,0.,1.));\n#8=SURFACE_OF_REVOLUTION('',#1,#5);\n");
    const StepGeometry& g = parsed.g;
    // Circle frame: X = (1,0,0), Z = (0,-1,0), Y = Z × X = (0,0,1): C(t) = (3 + cos t, 0, sin t).
    auto at = [](double th, double t) {
        const double r = 3 + std::cos(t);
        return Vector3d(r * std::cos(th), r * std::sin(th), std::sin(t));
    };
    std::vector<Vector2d> st;
    for (int k = 0; k <= 16; ++k) st.emplace_back(kPi / 2 * k / 16, kPi / 2);
    for (int k = 0; k <= 16; ++k) st.emplace_back(kPi / 2, kPi / 2 + kPi * k / 16);
    for (int k = 0; k <= 16; ++k) st.emplace_back(kPi / 2 * (16 - k) / 16, 3 * kPi / 2);
    for (int k = 0; k <= 16; ++k) st.emplace_back(0, 3 * kPi / 2 - kPi * k / 16);
    std::vector<Vector3d> b;
    for (const Vector2d& x : st) b.push_back(at(x.x(), x.y()));
    const StepGeometry::Surface s = g.surface(8, b);
    ASSERT_TRUE(s.map.u.arc.has_value());
    EXPECT_EQ(s.map.u.arc->theta0(), 0.0);  // the whole generatrix circle
    EXPECT_NEAR(s.map.u.arc->theta1(), 2 * kPi, 1e-15);
    expect_on_surface(s, b, st, 1e-9);
}

// ---- Malformed and unsupported entities ---------------------------------------------

// Calls f, expecting a ReadError on `line` whose reason contains `words`.
template <class F>
void expect_read_error(F f, int line, const std::string& words) {
    try {
        f();
        ADD_FAILURE() << "no ReadError; expected: " << words;
    } catch (const geom::ReadError& e) {
        EXPECT_EQ(e.file(), "t.stp");
        EXPECT_EQ(e.line(), line) << e.what();
        EXPECT_NE(e.reason().find(words), std::string::npos) << e.what();
    }
}

// Data lines start on line 8 of part21()'s text.
constexpr int kLine1 = 8;

TEST(StepGeometry, MalformedEntitiesNameTheirId) {
    const StepPart21 f = parse(
        "#1=DIRECTION('',(0.,0.,0.));\n"                                   // line 8
        "#2=AXIS2_PLACEMENT_3D('',#3,#1,$);\n"                             // 9
        "#3=CARTESIAN_POINT('',(0.,0.,0.));\n"                             // 10
        "#4=CIRCLE('',#6,-1.);\n"                                          // 11
        "#5=LINE('',#99,#7);\n"                                            // 12
        "#6=AXIS2_PLACEMENT_3D('',#3,$,$);\n"                              // 13
        "#7=VECTOR('',#8,1.);\n"                                           // 14
        "#8=DIRECTION('',(1.,0.,0.));\n"                                   // 15
        "#9=TRIMMED_CURVE('',#9,(PARAMETER_VALUE(0.)),(PARAMETER_VALUE(1.)),.T.,.PARAMETER.);\n"  // 16
        "#10=B_SPLINE_CURVE_WITH_KNOTS('',1,(#3,#3),.UNSPECIFIED.,.F.,.F.,(2,1),(0.,1.),.UNSPECIFIED.);\n"  // 17
        "#11=CIRCLE('',#3,1.);\n"                                          // 18
        "#12=CYLINDRICAL_SURFACE('',#6,0.);\n"                             // 19
        "#13=B_SPLINE_CURVE_WITH_KNOTS('',1,(#3,#3),.UNSPECIFIED.,.F.,.F.,(2,2),(1.,0.),.UNSPECIFIED.);\n"  // 20
        "#14=LINE('',#3);\n");                                             // 21
    const StepGeometry g(f);
    const Vector3d a(1, 0, 0), b(0, 1, 0);
    expect_read_error([&] { g.placement(2); }, kLine1, "#1 DIRECTION: direction_ratios are zero");
    expect_read_error([&] { g.edge_curve(4, a, b, true, 1e-9); }, kLine1 + 3, "#4 CIRCLE: radius -1 must be > 0");
    expect_read_error([&] { g.edge_curve(5, a, b, true, 1e-9); }, kLine1 + 4, "#5 LINE: pnt #99 is not defined");
    expect_read_error([&] { g.edge_curve(9, a, b, true, 1e-9); }, kLine1 + 8, "#9 TRIMMED_CURVE: references nest");
    expect_read_error([&] { g.edge_curve(10, a, b, true, 1e-9); }, kLine1 + 9,
                      "#10 B_SPLINE_CURVE_WITH_KNOTS: multiplicities sum to 3, expected 4");
    expect_read_error([&] { g.edge_curve(11, a, b, true, 1e-9); }, kLine1 + 10,
                      "#11 CIRCLE: position #3 is a CARTESIAN_POINT, expected AXIS2_PLACEMENT_3D");
    expect_read_error([&] { g.surface(12, {a, b}); }, kLine1 + 11, "#12 CYLINDRICAL_SURFACE: radius 0 must be > 0");
    expect_read_error([&] { g.edge_curve(13, a, b, true, 1e-9); }, kLine1 + 12, "#13 B_SPLINE_CURVE_WITH_KNOTS: knots decrease");
    expect_read_error([&] { g.edge_curve(14, a, b, true, 1e-9); }, kLine1 + 13, "#14 LINE: has 2 parameters, expected 3");
    try {
        g.point(77);
        ADD_FAILURE() << "no ReadError for an undefined instance";
    } catch (const geom::ReadError& e) {
        EXPECT_NE(e.reason().find("#77"), std::string::npos) << e.what();
    }
}

// ---- Boundary extents -------------------------------------------------------------------

TEST(BoundaryExtent, AnglesJoinAlongTheBoundaryAndWholeTurnsStartAtZero) {
    // A quarter arc sampled in order, then a point on it: the three quarters are the gap.
    AngularExtent e = angular_extent({3.0, 3.2, 3.4, 3.6, 3.3}, 0.0);
    EXPECT_FALSE(e.full);
    EXPECT_NEAR(e.lo, 3.0, 1e-14);
    EXPECT_NEAR(e.hi, 3.6, 1e-14);
    // Across angle π: -3.0 is 2π - 3.0 ≈ 3.28 and joined to 3.0 backwards.
    e = angular_extent({-3.0, 3.0, 2.8}, 0.0);
    EXPECT_NEAR(e.lo, 2.8, 1e-14);
    EXPECT_NEAR(e.hi, 2 * kPi - 3.0, 1e-14);
    // Twelve points round the circle in order: a whole turn; so is a single point.
    std::vector<double> round;
    for (int k = 0; k < 13; ++k) round.push_back(0.3 + 2 * kPi * k / 12);
    EXPECT_TRUE(angular_extent(round, 0.02).full);
    EXPECT_TRUE(angular_extent({1.0, 1.0}, 0.02).full);
    EXPECT_TRUE(angular_extent({}, 0.02).full);
    // Unjoined points (steps above kMaxJoinedAngleStep) leave their gaps open.
    e = angular_extent({0.0, 1.0, 2.0, 3.0}, 0.0);
    EXPECT_NEAR(e.lo, 0.0, 1e-14);
    EXPECT_NEAR(e.hi, 3.0, 1e-14);
    const auto [lo, hi] = padded_extent({2.0, 1.0, 3.0}, 0.1);
    EXPECT_DOUBLE_EQ(lo, 0.8);
    EXPECT_DOUBLE_EQ(hi, 3.2);
}

// ---- A shared file ------------------------------------------------------------------------

// The references of instance `id`'s only record.
const std::vector<StepValue>& params_of(const StepPart21& f, long long id) {
    const StepInstance* i = f.find(id);
    EXPECT_NE(i, nullptr) << "#" << id;
    return i->records.at(0).params;
}

TEST(StepGeometry, ScrewSurfacesAndEdgesTranslate) {
    TRIMKIT_CAD_SAMPLE(path, "step/screw.step");
    std::ifstream in(path, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const StepPart21 f = StepPart21::parse(text, path);
    const StepGeometry g(f);
    auto vertex = [&](const StepValue& v) { return g.point(params_of(f, v.integer).at(1).integer); };
    // Every EDGE_CURVE between its vertices.
    int edges = 0;
    for (const StepInstance* e : f.of_type("EDGE_CURVE")) {
        const std::vector<StepValue>& p = e->records[0].params;
        const Vector3d a = vertex(p[1]), b = vertex(p[2]);
        const geom::NurbsCurve3d c = g.edge_curve(p[3].integer, a, b, p[4].text == "T", 1e-6);
        EXPECT_LE((c.evaluate(c.domain().first) - a).norm(), 1e-6) << "#" << e->id;
        EXPECT_LE((c.evaluate(c.domain().second) - b).norm(), 1e-6) << "#" << e->id;
        ++edges;
    }
    EXPECT_EQ(edges, 22);
    // Every face's surface, sized by its edges' vertices, then by 16 points per edge.
    std::set<std::string> kinds;
    int faces = 0;
    for (const StepInstance* face : f.of_type("ADVANCED_FACE")) {
        const std::vector<StepValue>& p = face->records[0].params;
        std::vector<Vector3d> vertices, samples;
        for (const StepValue& bound : p[1].items) {
            const StepValue& loop = params_of(f, bound.integer).at(1);
            const StepInstance* l = f.find(loop.integer);
            if (l->records[0].type == "VERTEX_LOOP") {
                vertices.push_back(vertex(l->records[0].params[1]));
                samples.push_back(vertices.back());
                continue;
            }
            for (const StepValue& oe : l->records[0].params[1].items) {
                const std::vector<StepValue>& o = params_of(f, oe.integer);
                const std::vector<StepValue>& e = params_of(f, o.at(3).integer);
                const Vector3d a = vertex(e[1]), b = vertex(e[2]);
                vertices.push_back(a);
                vertices.push_back(b);
                const geom::NurbsCurve3d c = g.edge_curve(e[3].integer, a, b, e[4].text == "T", 1e-6);
                const auto [t0, t1] = c.domain();
                const bool forward = o.at(4).text == "T";
                for (int k = 0; k < 16; ++k) samples.push_back(c.evaluate(forward ? t0 + (t1 - t0) * k / 16 : t1 - (t1 - t0) * k / 16));
            }
        }
        const StepGeometry::Surface s = g.surface(p[2].integer, vertices);
        EXPECT_FALSE(s.kind.empty());
        const StepGeometry::Surface dense = g.surface(p[2].integer, samples);
        EXPECT_EQ(dense.kind, s.kind);
        // The dense boundary lies within the patch's control box (convex hull property).
        Eigen::AlignedBox3d box = dense.nurbs.control_box();
        box.extend(box.min() - Vector3d::Constant(1e-6)).extend(box.max() + Vector3d::Constant(1e-6));
        for (const Vector3d& x : samples) EXPECT_TRUE(box.contains(x)) << "#" << face->id << " " << s.kind;
        kinds.insert(s.kind);
        ++faces;
    }
    EXPECT_GT(faces, 0);
    EXPECT_TRUE(kinds.count("torus") && kinds.count("cone") && kinds.count("cylinder")) << kinds.size();
}

// ---- PCURVEs (ISO 10303-42 4.4.x surface_curve: the 2D curve shares curve_3d's parameter) ----

// A 2D context for DEFINITIONAL_REPRESENTATIONs (the reader does not look into it).
const std::string kContext2d =
    "#99=(GEOMETRIC_REPRESENTATION_CONTEXT(2) PARAMETRIC_REPRESENTATION_CONTEXT() "
    "REPRESENTATION_CONTEXT('2D SPACE',''));\n";

// A PCURVE #id on surface #surface whose representation #(id+1) holds the 2D curve #item.
std::string pcurve(int id, int surface, int item) {
    const std::string n = std::to_string(id), r = std::to_string(id + 1);
    return "#" + n + "=PCURVE('',#" + std::to_string(surface) + ",#" + r + ");\n#" + r +
           "=DEFINITIONAL_REPRESENTATION('',(#" + std::to_string(item) + "),#99);\n";
}

// A 2D LINE #id through (x, y) along (dx, dy) with speed 1 (#id+1..#id+3 its parts).
std::string line2d(int id, const std::string& xy, const std::string& d) {
    const std::string n = std::to_string(id), p = std::to_string(id + 1), v = std::to_string(id + 2),
                      dir = std::to_string(id + 3);
    return "#" + n + "=LINE('',#" + p + ",#" + v + ");\n#" + p + "=CARTESIAN_POINT('',(" + xy + "));\n#" + v +
           "=VECTOR('',#" + dir + ",1.);\n#" + dir + "=DIRECTION('',(" + d + "));\n";
}

// The circle #1 about (1,2,3) (radius 2) on the cylinder #5 of the same frame, as a
// SURFACE_CURVE #50 whose PCURVE #51 on #5 is the line v = 0, u = t (angles in degrees).
const std::string kCircleOnCylinder = kCircle + kContext2d + "#5=CYLINDRICAL_SURFACE('',#10,2.);\n" +
                                      "#50=SURFACE_CURVE('',#1,(#51),.PCURVE_S1.);\n" + pcurve(51, 5, 60) +
                                      line2d(60, "0.,0.", "1.,0.");

TEST(StepGeometry, PcurveOfACircleOnACylinderFollowsTheEdgeInDegrees) {
    const Parsed parsed(kCircleOnCylinder, kPi / 180);
    const StepGeometry& g = parsed.g;
    const Vector3d a(3, 2, 3), b(1, 4, 3);  // angles 0 and 90 degrees
    const StepGeometry::Surface S = g.surface(5, arc_points(2, 0, 0, 2 * kPi, 16, Vector3d(1, 2, 3)));
    for (bool same_sense : {true, false}) {
        StepGeometry::EdgeRange range;
        g.edge_curve(50, a, b, same_sense, 1e-9, &range);
        // The circle's parameter in the file's unit: 0 to 90 degrees, or down to -270.
        EXPECT_NEAR(range.start, 0, 1e-12);
        EXPECT_NEAR(range.end, same_sense ? 90 : -270, 1e-12);
        EXPECT_NEAR(range.period, 360, 1e-12);
        const std::optional<geom::NurbsCurve2d> pc = g.edge_pcurve(50, 5, range, true);
        ASSERT_TRUE(pc.has_value());
        EXPECT_LE((pc->evaluate(pc->domain().first) - Vector2d(0, 0)).norm(), 1e-12);
        EXPECT_LE((pc->evaluate(pc->domain().second) - Vector2d(range.end, 0)).norm(), 1e-12);
        const std::optional<geom::NurbsCurve2d> uv = g.map_pcurve(S, *pc);
        ASSERT_TRUE(uv.has_value());
        // On the surface: the circle from a to b, through -135 degrees when against it.
        const double t0 = uv->domain().first, t1 = uv->domain().second;
        auto on_surface = [&](double t) {
            const Vector2d q = uv->evaluate(t);
            return S.nurbs.evaluate(q.x(), q.y());
        };
        expect_near(on_surface(t0), a, 1e-9);
        expect_near(on_surface(t1), b, 1e-9);
        const double mid = (same_sense ? 45 : -135) * kPi / 180;
        const Vector3d middle(1 + 2 * std::cos(mid), 2 + 2 * std::sin(mid), 3);
        double nearest = 1e300;
        for (int k = 0; k <= 64; ++k) {
            const Vector3d x = on_surface(t0 + (t1 - t0) * k / 64);
            EXPECT_NEAR((x - Vector3d(1, 2, 3)).norm(), 2, 1e-9);
            nearest = std::min(nearest, (x - middle).norm());
        }
        EXPECT_LE(nearest, 2 * kPi * 2 / 64);  // one sample step of the longer arc
    }
}

TEST(StepGeometry, SeamCurveTakesThePcurveTheOrientationNames) {
    // The cylinder's seam line x = 3 (angle 0), t = height above z = 3; its two PCURVEs
    // u = 0 and u = 2π (radians).
    const Parsed parsed(kCircle + kContext2d + "#5=CYLINDRICAL_SURFACE('',#10,2.);\n" +
                        "#30=LINE('',#31,#32);\n#31=CARTESIAN_POINT('',(3.,2.,3.));\n#32=VECTOR('',#11,1.);\n"
                        "#50=SEAM_CURVE('',#30,(#51,#53),.PCURVE_S1.);\n" +
                        pcurve(51, 5, 60) + pcurve(53, 5, 70) + line2d(60, "0.,0.", "0.,1.") +
                        line2d(70, "6.283185307179586,0.", "0.,1."));
    const StepGeometry& g = parsed.g;
    StepGeometry::EdgeRange range;
    g.edge_curve(50, Vector3d(3, 2, 4), Vector3d(3, 2, 6), true, 1e-9, &range);
    EXPECT_NEAR(range.start, 1, 1e-12);
    EXPECT_NEAR(range.end, 3, 1e-12);
    EXPECT_EQ(range.period, 0.0);
    const std::optional<geom::NurbsCurve2d> first = g.edge_pcurve(50, 5, range, true);
    const std::optional<geom::NurbsCurve2d> second = g.edge_pcurve(50, 5, range, false);
    ASSERT_TRUE(first && second);
    EXPECT_LE((first->evaluate(first->domain().first) - Vector2d(0, 1)).norm(), 1e-15);
    EXPECT_LE((first->evaluate(first->domain().second) - Vector2d(0, 3)).norm(), 1e-15);
    EXPECT_LE((second->evaluate(second->domain().first) - Vector2d(2 * kPi, 1)).norm(), 1e-15);
}

TEST(StepGeometry, BSplinePcurveIsCutToTheEdgesRangeInItsSense) {
    // A degree-1 B-spline from (0,0,0) to (4,0,0) on [0, 4] on the plane z = 0, its
    // PCURVE the same segment in (u, v).
    const Parsed parsed(frame("0.,0.,0.") + kContext2d + "#5=PLANE('',#10);\n" +
                        "#30=B_SPLINE_CURVE_WITH_KNOTS('',1,(#31,#32),.UNSPECIFIED.,.F.,.F.,(2,2),(0.,4.),"
                        ".UNSPECIFIED.);\n#31=CARTESIAN_POINT('',(0.,0.,0.));\n#32=CARTESIAN_POINT('',(4.,0.,0.));\n"
                        "#50=SURFACE_CURVE('',#30,(#51),.PCURVE_S1.);\n" + pcurve(51, 5, 60) +
                        "#60=B_SPLINE_CURVE_WITH_KNOTS('',1,(#61,#62),.UNSPECIFIED.,.F.,.F.,(2,2),(0.,4.),"
                        ".UNSPECIFIED.);\n#61=CARTESIAN_POINT('',(0.,0.));\n#62=CARTESIAN_POINT('',(4.,0.));\n");
    const StepGeometry& g = parsed.g;
    for (bool same_sense : {true, false}) {
        const Vector3d from = same_sense ? Vector3d(1, 0, 0) : Vector3d(3, 0, 0), to(4 - from.x(), 0, 0);
        StepGeometry::EdgeRange range;
        g.edge_curve(50, from, to, same_sense, 1e-9, &range);
        const std::optional<geom::NurbsCurve2d> pc = g.edge_pcurve(50, 5, range, true);
        ASSERT_TRUE(pc.has_value());
        EXPECT_LE((pc->evaluate(pc->domain().first) - from.head<2>()).norm(), 1e-12);
        EXPECT_LE((pc->evaluate(pc->domain().second) - to.head<2>()).norm(), 1e-12);
        const StepGeometry::Surface S = g.surface(5, {from, to, Vector3d(2, 1, 0)});
        const std::optional<geom::NurbsCurve2d> uv = g.map_pcurve(S, *pc);
        ASSERT_TRUE(uv.has_value());
        EXPECT_LE((uv->evaluate(uv->domain().second) - to.head<2>()).norm(), 1e-12);  // a plane maps as it is
    }
    // A range the bounded PCURVE does not cover.
    EXPECT_FALSE(g.edge_pcurve(50, 5, StepGeometry::EdgeRange{3, 5, 0}, true).has_value());
}

TEST(StepGeometry, PcurvesThatCannotServeGiveNothing) {
    const Parsed parsed(kCircleOnCylinder + "#6=CYLINDRICAL_SURFACE('',#10,2.);\n" +
                        // #80: its only PCURVE lies on another surface instance (#6).
                        "#80=SURFACE_CURVE('',#1,(#81),.PCURVE_S1.);\n" + pcurve(81, 6, 60) +
                        // #83: a 2D kind not translated.
                        "#83=SURFACE_CURVE('',#1,(#84),.PCURVE_S1.);\n" + pcurve(84, 5, 86) +
                        "#86=HYPERBOLA('',#10,1.,1.);\n"
                        // #87: a representation that is not defined.
                        "#87=SURFACE_CURVE('',#1,(#88),.PCURVE_S1.);\n#88=PCURVE('',#5,#500);\n"
                        // #89: a 2D curve with 3D points (a line along z).
                        "#89=SURFACE_CURVE('',#1,(#90),.PCURVE_S1.);\n" + pcurve(90, 5, 92) +
                        "#92=LINE('',#13,#93);\n#93=VECTOR('',#11,1.);\n"
                        // #94: a curve in a cycle of TRIMMED_CURVEs.
                        "#94=SURFACE_CURVE('',#1,(#95),.PCURVE_S1.);\n" + pcurve(95, 5, 97) +
                        "#97=TRIMMED_CURVE('',#97,(PARAMETER_VALUE(0.)),(PARAMETER_VALUE(1.)),.T.,.PARAMETER.);\n");
    const StepGeometry& g = parsed.g;
    const StepGeometry::EdgeRange range{0, 0.5 * kPi, 2 * kPi};
    EXPECT_TRUE(g.edge_pcurve(50, 5, range, true).has_value());  // the good one, for contrast
    for (long long id : {80, 83, 87, 89, 94}) EXPECT_FALSE(g.edge_pcurve(id, 5, range, true).has_value()) << id;
    EXPECT_FALSE(g.edge_pcurve(1, 5, range, true).has_value());    // a bare CIRCLE: no PCURVEs
    EXPECT_FALSE(g.edge_pcurve(777, 5, range, true).has_value());  // not defined
    EXPECT_FALSE(g.edge_pcurve(50, 5, StepGeometry::EdgeRange{1, 1, 0}, true).has_value());  // empty range
}

}  // namespace
}  // namespace trimkit::io
