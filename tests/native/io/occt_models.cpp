#include "io/occt_models.h"

#include <cmath>
#include <stdexcept>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepGProp.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <GProp_GProps.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <GCE2d_MakeSegment.hxx>
#include <BRepLib.hxx>
#include <BRepAdaptor_Curve.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <TopExp_Explorer.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepTools.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <TopoDS_Shell.hxx>
#include <TopoDS_Solid.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRep_Builder.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <GC_MakeSegment.hxx>
#include <Geom2d_Line.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Circle.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <STEPCAFControl_Writer.hxx>
#include <STEPControl_Writer.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <gp_Ax2.hxx>
#include <gp_Ax3.hxx>
#include <gp_Circ.hxx>
#include <gp_Lin2d.hxx>
#include <gp_Trsf.hxx>

namespace trimkit::test {

void write_plate_with_holes_step(const std::string& path, double L, double W, double H,
                                 const std::vector<Eigen::Vector2d>& centres, double r) {
    TopoDS_Shape plate = BRepPrimAPI_MakeBox(L, W, H).Shape();
    for (const Eigen::Vector2d& c : centres) {
        const gp_Ax2 axis(gp_Pnt(c.x(), c.y(), -1.0), gp_Dir(0, 0, 1));
        plate = BRepAlgoAPI_Cut(plate, BRepPrimAPI_MakeCylinder(axis, r, H + 2.0).Shape()).Shape();
    }
    STEPControl_Writer writer;
    if (writer.Transfer(plate, STEPControl_AsIs) != IFSelect_RetDone || writer.Write(path.c_str()) != IFSelect_RetDone)
        throw std::runtime_error("cannot write " + path);
}

void write_cylinder_face_brep(const std::string& path, double R, double h, double u0, double u1) {
    Handle(Geom_CylindricalSurface) cylinder = new Geom_CylindricalSurface(gp_Ax3(gp::XOY()), R);
    const TopoDS_Face face = BRepBuilderAPI_MakeFace(cylinder, u0, u1, 0.0, h, 1e-7).Face();
    if (!BRepTools::Write(face, path.c_str())) throw std::runtime_error("cannot write " + path);
}

void write_helical_strip_brep(const std::string& path, double R, double k, double w, double sweep) {
    Handle(Geom_CylindricalSurface) cylinder = new Geom_CylindricalSurface(gp_Ax3(gp::XOY()), R);
    const gp_Pnt2d a(0, 0), b(sweep, k * sweep), c(sweep, k * sweep + w), d(0, w);
    auto edge = [&](const gp_Pnt2d& p, const gp_Pnt2d& q) {
        return BRepBuilderAPI_MakeEdge(GCE2d_MakeSegment(p, q).Value(), cylinder).Edge();
    };
    BRepBuilderAPI_MakeWire wire(edge(a, b), edge(b, c), edge(c, d), edge(d, a));
    if (!wire.IsDone()) throw std::runtime_error("helical strip: the wire does not close");
    TopoDS_Face face = BRepBuilderAPI_MakeFace(cylinder, wire.Wire(), true).Face();
    BRepLib::BuildCurves3d(face);
    if (!BRepTools::Write(face, path.c_str())) throw std::runtime_error("cannot write " + path);
}

void write_damaged_cylinder_face_brep(const std::string& path, double R, double h, double gap,
                                      double vertex_tolerance) {
    Handle(Geom_CylindricalSurface) cylinder = new Geom_CylindricalSurface(gp_Ax3(gp::XOY()), R);
    BRep_Builder b;
    const double q = M_PI / 2;
    const gp_Pnt p00(R, 0, 0), p10(0, R, 0), p11(0, R, h), p01(R, 0, h);
    TopoDS_Vertex v00, v10, v11, v01;
    for (auto [v, p] : {std::pair{&v00, p00}, {&v10, p10}, {&v11, p11}, {&v01, p01}})
        b.MakeVertex(*v, p, vertex_tolerance);
    const gp_Circ bottom(gp_Ax2(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1), gp_Dir(1, 0, 0)), R);
    const gp_Circ top(gp_Ax2(gp_Pnt(0, 0, h), gp_Dir(0, 0, 1), gp_Dir(1, 0, 0)), R);
    TopoDS_Face face;
    b.MakeFace(face, cylinder, 1e-7);
    // Edges with 3D curves and p-curves: (u, v) = (θ, z).
    auto edge = [&](const Handle(Geom_Curve)& c, double f, double l, const TopoDS_Vertex& a,
                    const TopoDS_Vertex& z, const Handle(Geom2d_Curve)& pc) {
        TopoDS_Edge e;
        b.MakeEdge(e, c, 1e-7);
        b.Add(e, a.Oriented(TopAbs_FORWARD));
        b.Add(e, z.Oriented(TopAbs_REVERSED));
        b.Range(e, f, l);
        if (!pc.IsNull()) b.UpdateEdge(e, pc, face, 1e-7);
        return e;
    };
    const Handle(Geom2d_Curve) bottom_pc =
        gap > 0 ? Handle(Geom2d_Curve)(new Geom2d_Line(gp_Pnt2d(0, gap), gp_Dir2d(1, 0))) : Handle(Geom2d_Curve)();
    const TopoDS_Edge e0 = edge(new Geom_Circle(bottom), 0, q, v00, v10, bottom_pc);
    const TopoDS_Edge e1 = edge(GC_MakeSegment(p10, p11).Value(), 0, h, v10, v11,
                                new Geom2d_Line(gp_Pnt2d(q, 0), gp_Dir2d(0, 1)));
    const TopoDS_Edge e2 = edge(new Geom_Circle(top), 0, q, v01, v11, new Geom2d_Line(gp_Pnt2d(0, h), gp_Dir2d(1, 0)));
    const TopoDS_Edge e3 = edge(GC_MakeSegment(p00, p01).Value(), 0, h, v00, v01,
                                new Geom2d_Line(gp_Pnt2d(0, 0), gp_Dir2d(0, 1)));
    TopoDS_Wire wire;
    b.MakeWire(wire);
    b.Add(wire, e0);
    b.Add(wire, e1);
    b.Add(wire, e2.Reversed());
    b.Add(wire, e3.Reversed());
    b.Add(face, wire);
    if (!BRepTools::Write(face, path.c_str())) throw std::runtime_error("cannot write " + path);
}

void write_slow_corner_face_brep(const std::string& path, double L, double gap) {
    TColgp_Array2OfPnt poles(1, 3, 1, 2);
    const double x[3] = {0, 0, L};
    for (int i = 1; i <= 3; ++i)
        for (int j = 1; j <= 2; ++j) poles(i, j) = gp_Pnt(x[i - 1], L * (j - 1), 0);
    TColStd_Array1OfReal knots(1, 2);
    knots(1) = 0;
    knots(2) = 1;
    TColStd_Array1OfInteger mults_u(1, 2), mults_v(1, 2);
    mults_u(1) = mults_u(2) = 3;
    mults_v(1) = mults_v(2) = 2;
    Handle(Geom_BSplineSurface) surface = new Geom_BSplineSurface(poles, knots, knots, mults_u, mults_v, 2, 1);
    BRep_Builder b;
    const double corner = L * gap * gap, vertex_tolerance = 2 * corner;
    TopoDS_Vertex v00, v10, v11, v01;
    b.MakeVertex(v00, gp_Pnt(0, 0, 0), vertex_tolerance);
    b.MakeVertex(v10, gp_Pnt(L, 0, 0), 1e-7);
    b.MakeVertex(v11, gp_Pnt(L, L, 0), 1e-7);
    b.MakeVertex(v01, gp_Pnt(0, L, 0), 1e-7);
    TopoDS_Face face;
    b.MakeFace(face, surface, 1e-7);
    // Straight edges; each p-curve a line in (u,v) over the edge's own range.
    auto edge = [&](const gp_Pnt& p, const gp_Pnt& q, const TopoDS_Vertex& a, const TopoDS_Vertex& z,
                    const gp_Pnt2d& s, const gp_Pnt2d& t) {
        TopoDS_Edge e;
        b.MakeEdge(e, GC_MakeSegment(p, q).Value(), vertex_tolerance);
        b.Add(e, a.Oriented(TopAbs_FORWARD));
        b.Add(e, z.Oriented(TopAbs_REVERSED));
        const double length = p.Distance(q);
        b.Range(e, 0, length);
        const gp_Vec2d d(s, t);
        b.UpdateEdge(e, new Geom2d_Line(s, gp_Dir2d(d)), face, vertex_tolerance);
        b.Range(e, face, 0, d.Magnitude());
        return e;
    };
    const TopoDS_Edge bottom = edge(gp_Pnt(corner, 0, 0), gp_Pnt(L, 0, 0), v00, v10, {gap, 0}, {1, 0});
    const TopoDS_Edge right = edge(gp_Pnt(L, 0, 0), gp_Pnt(L, L, 0), v10, v11, {1, 0}, {1, 1});
    const TopoDS_Edge top = edge(gp_Pnt(L, L, 0), gp_Pnt(0, L, 0), v11, v01, {1, 1}, {0, 1});
    const TopoDS_Edge left = edge(gp_Pnt(0, L, 0), gp_Pnt(0, 0, 0), v01, v00, {0, 1}, {0, 0});
    TopoDS_Wire wire;
    b.MakeWire(wire);
    for (const TopoDS_Edge& e : {bottom, right, top, left}) b.Add(wire, e);
    b.Add(face, wire);
    if (!BRepTools::Write(face, path.c_str())) throw std::runtime_error("cannot write " + path);
}

void write_bspline_face_past_domain_brep(const std::string& path, double L, double m) {
    TColgp_Array2OfPnt poles(1, 2, 1, 2);
    for (int i = 1; i <= 2; ++i)
        for (int j = 1; j <= 2; ++j) poles(i, j) = gp_Pnt(L * (i - 1), L * (j - 1), 0);
    TColStd_Array1OfReal knots(1, 2);
    knots(1) = 0;
    knots(2) = 1;
    TColStd_Array1OfInteger mults(1, 2);
    mults(1) = mults(2) = 2;
    Handle(Geom_BSplineSurface) surface = new Geom_BSplineSurface(poles, knots, knots, mults, mults, 1, 1);
    BRep_Builder b;
    TopoDS_Face face;
    b.MakeFace(face, surface, 1e-7);
    const double lo = -m, hi = 1 + m;
    const gp_Pnt2d uv[4] = {{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}};
    TopoDS_Vertex v[4];
    for (int k = 0; k < 4; ++k) b.MakeVertex(v[k], gp_Pnt(L * uv[k].X(), L * uv[k].Y(), 0), 1e-7);
    TopoDS_Wire wire;
    b.MakeWire(wire);
    for (int k = 0; k < 4; ++k) {
        const gp_Pnt2d a = uv[k], z = uv[(k + 1) % 4];
        const double length = a.Distance(z);
        TopoDS_Edge e;
        b.MakeEdge(e, GC_MakeSegment(gp_Pnt(L * a.X(), L * a.Y(), 0), gp_Pnt(L * z.X(), L * z.Y(), 0)).Value(), 1e-7);
        b.Add(e, v[k].Oriented(TopAbs_FORWARD));
        b.Add(e, v[(k + 1) % 4].Oriented(TopAbs_REVERSED));
        b.Range(e, 0, L * length);
        // The p-curve runs with the 3D segment's parameter (arc length in model units).
        TColgp_Array1OfPnt2d ends(1, 2);
        ends(1) = a;
        ends(2) = z;
        TColStd_Array1OfReal range(1, 2);
        range(1) = 0;
        range(2) = L * length;
        b.UpdateEdge(e, new Geom2d_BSplineCurve(ends, range, mults, 1), face, 1e-7);
        b.Add(wire, e);
    }
    b.Add(face, wire);
    if (!BRepTools::Write(face, path.c_str())) throw std::runtime_error("cannot write " + path);
}

void write_box_assembly_step(const std::string& path, double dx, double dy, double dz,
                             const Eigen::Vector3d& t1, const Eigen::Vector3d& t2) {
    Handle(TDocStd_Document) doc;
    XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", doc);
    const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
    const TDF_Label part = shapes->AddShape(BRepPrimAPI_MakeBox(dx, dy, dz).Shape(), false);
    TDataStd_Name::Set(part, "block");
    const TDF_Label assembly = shapes->NewShape();
    TDataStd_Name::Set(assembly, "pair");
    gp_Trsf a, b;
    a.SetTranslation(gp_Vec(t1.x(), t1.y(), t1.z()));
    b.SetRotation(gp::OZ(), M_PI / 2);
    gp_Trsf shift;
    shift.SetTranslation(gp_Vec(t2.x(), t2.y(), t2.z()));
    b = shift * b;
    shapes->AddComponent(assembly, part, TopLoc_Location(a));
    shapes->AddComponent(assembly, part, TopLoc_Location(b));
    shapes->UpdateAssemblies();
    STEPCAFControl_Writer writer;
    if (!writer.Transfer(doc, STEPControl_AsIs) || writer.Write(path.c_str()) != IFSelect_RetDone)
        throw std::runtime_error("cannot write " + path);
}

// An XCAF document's shape tool; the document stays open for the writer.
Handle(XCAFDoc_ShapeTool) new_xcaf_shapes(Handle(TDocStd_Document)& doc) {
    XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", doc);
    return XCAFDoc_DocumentTool::ShapeTool(doc->Main());
}

void write_xcaf_step(const Handle(TDocStd_Document)& doc, const std::string& path) {
    STEPCAFControl_Writer writer;
    if (!writer.Transfer(doc, STEPControl_AsIs) || writer.Write(path.c_str()) != IFSelect_RetDone)
        throw std::runtime_error("cannot write " + path);
}

TopLoc_Location translation(const Eigen::Vector3d& t) {
    gp_Trsf a;
    a.SetTranslation(gp_Vec(t.x(), t.y(), t.z()));
    return TopLoc_Location(a);
}

void write_nested_box_assembly_step(const std::string& path, double dx, double dy, double dz,
                                    const Eigen::Vector3d& t1, const Eigen::Vector3d& t2,
                                    const Eigen::Vector3d& s1, const Eigen::Vector3d& s2) {
    Handle(TDocStd_Document) doc;
    const Handle(XCAFDoc_ShapeTool) shapes = new_xcaf_shapes(doc);
    const TDF_Label part = shapes->AddShape(BRepPrimAPI_MakeBox(dx, dy, dz).Shape(), false);
    TDataStd_Name::Set(part, "block");
    const TDF_Label pair = shapes->NewShape();
    TDataStd_Name::Set(pair, "pair");
    shapes->AddComponent(pair, part, translation(t1));
    shapes->AddComponent(pair, part, translation(t2));
    const TDF_Label top = shapes->NewShape();
    TDataStd_Name::Set(top, "top");
    shapes->AddComponent(top, pair, translation(s1));
    gp_Trsf turn;
    turn.SetRotation(gp::OX(), M_PI / 2);
    gp_Trsf shift;
    shift.SetTranslation(gp_Vec(s2.x(), s2.y(), s2.z()));
    shapes->AddComponent(top, pair, TopLoc_Location(shift * turn));
    shapes->UpdateAssemblies();
    write_xcaf_step(doc, path);
}

void write_doubling_assembly_step(const std::string& path, int levels) {
    Handle(TDocStd_Document) doc;
    const Handle(XCAFDoc_ShapeTool) shapes = new_xcaf_shapes(doc);
    TDF_Label below = shapes->AddShape(BRepPrimAPI_MakeBox(1, 1, 1).Shape(), false);
    for (int k = 0; k < levels; ++k) {
        const TDF_Label level = shapes->NewShape();
        shapes->AddComponent(level, below, translation(Eigen::Vector3d::Zero()));
        shapes->AddComponent(level, below, translation(Eigen::Vector3d(std::ldexp(2.0, k), 0, 0)));
        below = level;
    }
    shapes->UpdateAssemblies();
    write_xcaf_step(doc, path);
}

namespace {

double area_of(const TopoDS_Shape& shape) {
    GProp_GProps props;
    BRepGProp::SurfaceProperties(shape, props);
    return props.Mass();
}

bool is_step_path(const std::string& path) {
    return path.size() > 4 && (path.compare(path.size() - 4, 4, ".stp") == 0 || path.compare(path.size() - 5, 5, ".step") == 0);
}

// IGES, or STEP (AP214, as OCCT writes it) when the path ends in .stp or .step.
double write_iges(const TopoDS_Shape& shape, const std::string& path, bool brep_mode) {
    if (is_step_path(path)) {
        STEPControl_Writer writer;
        if (writer.Transfer(shape, STEPControl_AsIs) != IFSelect_RetDone || writer.Write(path.c_str()) != IFSelect_RetDone)
            throw std::runtime_error("cannot write " + path);
        return area_of(shape);
    }
    IGESControl_Controller::Init();
    IGESControl_Writer writer("MM", brep_mode ? 1 : 0);
    if (!writer.AddShape(shape) || !writer.Write(path.c_str())) throw std::runtime_error("cannot write " + path);
    return area_of(shape);
}

double write_brep_mode_iges(const TopoDS_Shape& shape, const std::string& path) {
    return write_iges(shape, path, true);
}

}  // namespace

double write_cylinder_cross_hole_iges(const std::string& path, double R, double h, double r) {
    const TopoDS_Shape body = BRepPrimAPI_MakeCylinder(gp_Ax2(gp::Origin(), gp::DZ()), R, h).Shape();
    const gp_Ax2 across(gp_Pnt(-2 * R, 0, h / 2), gp::DX());
    return write_brep_mode_iges(BRepAlgoAPI_Cut(body, BRepPrimAPI_MakeCylinder(across, r, 4 * R).Shape()).Shape(),
                                path);
}

double write_sphere_cut_near_pole_iges(const std::string& path, double R, double c, double a, double r) {
    TopoDS_Shape ball = BRepPrimAPI_MakeSphere(R).Shape();
    ball = BRepAlgoAPI_Cut(ball, BRepPrimAPI_MakeBox(gp_Pnt(c, c, -2 * R), 2 * R, 2 * R, 4 * R).Shape()).Shape();
    const gp_Ax2 up(gp_Pnt(a, 0, 0), gp::DZ());
    return write_brep_mode_iges(BRepAlgoAPI_Cut(ball, BRepPrimAPI_MakeCylinder(up, r, 2 * R).Shape()).Shape(), path);
}

double write_ball_hole_on_seam_iges(const std::string& path, double R, double r, bool brep_mode) {
    const TopoDS_Shape ball = BRepPrimAPI_MakeSphere(R).Shape();
    const gp_Ax2 out(gp::Origin(), gp_Dir(1, 0, 0.6));
    return write_iges(BRepAlgoAPI_Cut(ball, BRepPrimAPI_MakeCylinder(out, r, 2 * R).Shape()).Shape(), path, brep_mode);
}

double write_perforated_ball(const std::string& path, double R, double r, int holes) {
    TopoDS_Shape ball = BRepPrimAPI_MakeSphere(R).Shape();
    for (int i = 0; i < holes; ++i) {
        const double a = 2 * M_PI * i / holes;
        const gp_Ax2 out(gp::Origin(), gp_Dir(std::cos(a), std::sin(a), 0.6));
        ball = BRepAlgoAPI_Cut(ball, BRepPrimAPI_MakeCylinder(out, r, 2 * R).Shape()).Shape();
    }
    gp_Trsf turn;
    turn.SetRotation(gp_Ax1(gp::Origin(), gp_Dir(1, 1, 0)), 0.7);
    return write_iges(BRepBuilderAPI_Transform(ball, turn).Shape(), path, true);
}

double write_whole_ball_iges(const std::string& path, double R, bool brep_mode) {
    return write_iges(BRepPrimAPI_MakeSphere(R).Shape(), path, brep_mode);
}

double write_revolved_arc_hole_iges(const std::string& path, double theta0, double theta1) {
    const gp_Pnt centre(30, 0, 0);
    const Handle(Geom_Circle) circle = new Geom_Circle(gp_Ax2(centre, gp::DY(), gp::DX()), 10);
    const Handle(Geom_SurfaceOfRevolution) surface = new Geom_SurfaceOfRevolution(circle, gp::OZ());
    const TopoDS_Face band = BRepBuilderAPI_MakeFace(surface, 0, 1.5 * M_PI, theta0, theta1, 1e-7).Face();
    // Drilled through the band's middle, obliquely to its normal and its meridian.
    const double m = 0.5 * (theta0 + theta1);
    const gp_Pnt middle = surface->Value(0.75 * M_PI, m);
    gp_Vec normal(gp_Pnt(30 * std::cos(0.75 * M_PI), 30 * std::sin(0.75 * M_PI), 0), middle);
    normal.Normalize();
    const gp_Vec along = normal + gp_Vec(0, 0, 0.3) + 0.4 * gp_Vec(-normal.Y(), normal.X(), 0);
    const gp_Ax2 drill(middle.Translated(-20 * along.Normalized()), gp_Dir(along));
    return write_iges(BRepAlgoAPI_Cut(band, BRepPrimAPI_MakeCylinder(drill, 3, 40).Shape()).Shape(), path, false);
}

double write_cone_apex_hole_iges(const std::string& path, double R, double h, double r, bool brep_mode) {
    const TopoDS_Shape cone = BRepPrimAPI_MakeCone(R, 0, h).Shape();
    const gp_Ax2 across(gp_Pnt(-4 * R / 3, 4 * R / 15, 0.3 * h), gp::DX());
    return write_iges(BRepAlgoAPI_Cut(cone, BRepPrimAPI_MakeCylinder(across, r, 8 * R / 3).Shape()).Shape(), path,
                      brep_mode);
}

double write_filleted_hole_block_iges(const std::string& path, bool brep_mode) {
    TopoDS_Shape block = BRepPrimAPI_MakeBox(80, 40, 20).Shape();
    block = BRepAlgoAPI_Cut(block, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(20, 20, -5), gp::DZ()), 8, 30).Shape()).Shape();
    block = BRepAlgoAPI_Cut(block, BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(60, 20, -5), gp::DZ()), 6, 30).Shape()).Shape();
    BRepFilletAPI_MakeFillet round(block);
    for (TopExp_Explorer e(block, TopAbs_EDGE); e.More(); e.Next())
        if (BRepAdaptor_Curve(TopoDS::Edge(e.Current())).GetType() == GeomAbs_Circle)
            round.Add(2.0, TopoDS::Edge(e.Current()));
    return write_iges(round.Shape(), path, brep_mode);
}

double write_rounded_box(const std::string& path, double a, double b, double c, double r) {
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(a, b, c).Shape();
    BRepFilletAPI_MakeFillet round(box);
    for (TopExp_Explorer e(box, TopAbs_EDGE); e.More(); e.Next()) round.Add(r, TopoDS::Edge(e.Current()));
    return write_iges(round.Shape(), path, true);
}

double write_sewn_rounded_box(const std::string& path) {
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(50, 40, 30).Shape();
    BRepFilletAPI_MakeFillet round(box);
    for (TopExp_Explorer e(box, TopAbs_EDGE); e.More(); e.Next()) round.Add(5.0, TopoDS::Edge(e.Current()));
    BRepBuilderAPI_Sewing sewing(1e-3);
    int k = 0;
    for (TopExp_Explorer e(round.Shape(), TopAbs_FACE); e.More(); e.Next(), ++k) {
        gp_Trsf t;
        t.SetTranslation(gp_Vec(1e-4 * std::sin(k), 1e-4 * std::cos(1.7 * k), 1e-4 * std::sin(2.9 * k)));
        sewing.Add(BRepBuilderAPI_Transform(e.Current(), t).Shape());
    }
    sewing.Perform();
    BRep_Builder b;
    TopoDS_Solid solid;
    b.MakeSolid(solid);
    for (TopExp_Explorer e(sewing.SewedShape(), TopAbs_SHELL); e.More(); e.Next()) {
        b.Add(solid, e.Current());
        break;
    }
    return write_iges(solid, path, true);
}

double write_loose_face_rounded_box(const std::string& path) {
    const TopoDS_Shape box = BRepPrimAPI_MakeBox(50, 40, 30).Shape();
    BRepFilletAPI_MakeFillet round(box);
    for (TopExp_Explorer e(box, TopAbs_EDGE); e.More(); e.Next()) round.Add(5.0, TopoDS::Edge(e.Current()));
    BRep_Builder b;
    TopoDS_Shell shell;
    b.MakeShell(shell);
    for (TopExp_Explorer e(round.Shape(), TopAbs_FACE); e.More(); e.Next())
        b.Add(shell, BRepBuilderAPI_Copy(e.Current()).Shape());
    if (is_step_path(path)) return write_iges(shell, path, true);
    if (!BRepTools::Write(shell, path.c_str())) throw std::runtime_error("cannot write " + path);
    return area_of(shell);
}

double write_torus_hole_on_seams_iges(const std::string& path) {
    const TopoDS_Shape ring = BRepPrimAPI_MakeTorus(40, 12).Shape();
    const gp_Ax2 radial(gp_Pnt(30, 0, 0), gp::DX());
    return write_brep_mode_iges(BRepAlgoAPI_Cut(ring, BRepPrimAPI_MakeCylinder(radial, 4, 40).Shape()).Shape(), path);
}

double write_frustum_hole_on_seam_iges(const std::string& path) {
    const TopoDS_Shape frustum = BRepPrimAPI_MakeCone(25, 12, 40).Shape();
    const gp_Ax2 across(gp_Pnt(-40, 0, 20), gp::DX());
    return write_brep_mode_iges(BRepAlgoAPI_Cut(frustum, BRepPrimAPI_MakeCylinder(across, 5, 80).Shape()).Shape(), path);
}

double write_periodic_spline_prism_brep(const std::string& path, const std::vector<Eigen::Vector2d>& outline,
                                        double h) {
    Handle(TColgp_HArray1OfPnt) points = new TColgp_HArray1OfPnt(1, static_cast<int>(outline.size()));
    for (std::size_t i = 0; i < outline.size(); ++i)
        points->SetValue(static_cast<int>(i) + 1, gp_Pnt(outline[i].x(), outline[i].y(), 0));
    GeomAPI_Interpolate interpolate(points, true, 1e-7);
    interpolate.Perform();
    const TopoDS_Wire wire = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(interpolate.Curve())).Wire();
    const TopoDS_Shape prism = BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(wire), gp_Vec(0, 0, h)).Shape();
    if (!BRepTools::Write(prism, path.c_str())) throw std::runtime_error("cannot write " + path);
    // BRepGProp is 2.6 % high on this prism's plane faces (their p-curves are computed
    // from the periodic curve), so the area comes from the outline itself: the enclosed
    // area by Green's theorem and the perimeter, both from dense samples of the spline
    // (trapezoids on a smooth periodic curve: far below 1e-6 relative).
    const Handle(Geom_BSplineCurve) curve = interpolate.Curve();
    constexpr int kSamples = 20000;
    const double t0 = curve->FirstParameter(), t1 = curve->LastParameter();
    double enclosed = 0, perimeter = 0;
    gp_Pnt prev = curve->Value(t0);
    for (int k = 1; k <= kSamples; ++k) {
        const gp_Pnt p = curve->Value(t0 + (t1 - t0) * k / kSamples);
        enclosed += 0.5 * (prev.X() * p.Y() - p.X() * prev.Y());
        perimeter += prev.Distance(p);
        prev = p;
    }
    return 2 * std::fabs(enclosed) + perimeter * h;
}

}  // namespace trimkit::test
