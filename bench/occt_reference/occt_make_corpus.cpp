// occt_make_corpus: builds a varied set of solids with Open CASCADE's modelling
// algorithms (primitives, booleans, fillets, chamfers, sweeps, lofts, shells) and writes
// each as STEP (AP214), IGES in B-rep mode (186/514), IGES in faces mode (144/142) and
// .brep, so that trimkit's readers and mesher meet the kinds of faces real CAD systems
// make (holes in planes, seams through trims, poles, apexes, blends, saddle curves)
// beyond the files in ../shared/data/cad. Run by hand, then bench/step_check_all.py
// --files on the output measures each file against OCCT's own reading.
// Usage: occt_make_corpus OUT_DIR     (prints one line per file written)
//        occt_make_corpus OUT_DIR --from-brep FILE.brep...   (each as STEP and both IGES modes)
// (26 solids since 2026-12-02: round 2 added poles inside holes, a hole where a torus's
// seams meet, an open revolution, a B-spline plate, filleted hole rims, offset surfaces,
// an ellipsoid of B-spline faces and a frustum with a hole on its seam; round 3 a coil
// swept along a helix, a revolution closing on its axis, an elliptic extrusion and a
// variable-radius fillet; round 4 a boss across a sphere's seam, a pipe elbow, a plate
// with a grid of holes and notches, a turned shaft, an equal-radius tee, a slotted tube,
// a cone capped by a sphere, a part 0.06 mm across, one 5e5 from the origin and a
// drafted box; round 5 (2026-12-05, after OCCT's own sample .brep files) a wavy block
// whose top is a B-spline of many spans edged by iso-lines, a boss fused onto it, an
// open shell, two solids in one file, a box sewn from faces 2e-4 apart, and a STEP
// file in inches.)

#include <BRepAdaptor_Curve.hxx>
#include <BRepAdaptor_Surface.hxx>
#include <BRepOffsetAPI_DraftAngle.hxx>
#include <gp_Ax3.hxx>
#include <gp_Pln.hxx>
#include <BRepAlgoAPI_Cut.hxx>
#include <BRepLib.hxx>
#include <BRepOffsetAPI_MakePipeShell.hxx>
#include <Geom2d_Line.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <gp_Elips.hxx>
#include <BRepBuilderAPI_GTransform.hxx>
#include <BRepOffsetAPI_MakeOffsetShape.hxx>
#include <GeomAPI_PointsToBSplineSurface.hxx>
#include <Geom_BSplineSurface.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <gp_GTrsf.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepFilletAPI_MakeChamfer.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepOffsetAPI_MakePipe.hxx>
#include <BRepOffsetAPI_MakeThickSolid.hxx>
#include <BRepOffsetAPI_ThruSections.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCone.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <GC_MakeCircle.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <GeomAPI_PointsToBSpline.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <TopoDS_Vertex.hxx>
#include <Geom_BSplineCurve.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Reader.hxx>
#include <STEPControl_Writer.hxx>
#include <Standard_Failure.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>
#include <gp_Trsf.hxx>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace {

gp_Ax2 axis_at(double x, double y, double z, gp_Dir dir = gp::DZ()) {
    return gp_Ax2(gp_Pnt(x, y, z), dir);
}

TopoDS_Shape cut(const TopoDS_Shape& a, const TopoDS_Shape& b) { return BRepAlgoAPI_Cut(a, b).Shape(); }
TopoDS_Shape fuse(const TopoDS_Shape& a, const TopoDS_Shape& b) { return BRepAlgoAPI_Fuse(a, b).Shape(); }

TopoDS_Shape rotated(const TopoDS_Shape& s, const gp_Ax1& axis, double angle) {
    gp_Trsf t;
    t.SetRotation(axis, angle);
    return BRepBuilderAPI_Transform(s, t, true).Shape();
}

// Every edge of `s` filleted with `radius` (edges the algorithm cannot blend make it throw).
TopoDS_Shape fillet_all(const TopoDS_Shape& s, double radius) {
    BRepFilletAPI_MakeFillet fillet(s);
    for (TopExp_Explorer e(s, TopAbs_EDGE); e.More(); e.Next()) fillet.Add(radius, TopoDS::Edge(e.Current()));
    return fillet.Shape();
}

TopoDS_Wire circle_wire(const gp_Ax2& axis, double radius) {
    return BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(gp_Circ(axis, radius))).Wire();
}

Handle(Geom_BSplineCurve) spline_through(const std::vector<gp_Pnt>& points) {
    TColgp_Array1OfPnt array(1, static_cast<int>(points.size()));
    for (size_t i = 0; i < points.size(); ++i) array.SetValue(static_cast<int>(i) + 1, points[i]);
    return GeomAPI_PointsToBSpline(array).Curve();
}

// A plate 100 x 60 x 10 with three through holes of different radii, outer edges filleted.
TopoDS_Shape plate_with_holes() {
    TopoDS_Shape plate = BRepPrimAPI_MakeBox(100, 60, 10).Shape();
    plate = fillet_all(plate, 2.0);
    plate = cut(plate, BRepPrimAPI_MakeCylinder(axis_at(20, 30, -5), 8, 20).Shape());
    plate = cut(plate, BRepPrimAPI_MakeCylinder(axis_at(50, 30, -5), 5, 20).Shape());
    return cut(plate, BRepPrimAPI_MakeCylinder(axis_at(80, 20, -5), 3, 20).Shape());
}

// A cylinder whose seam runs through a cross hole: the hole's trim crosses u = 0.
TopoDS_Shape cylinder_hole_on_seam() {
    TopoDS_Shape body = BRepPrimAPI_MakeCylinder(axis_at(0, 0, 0), 20, 60).Shape();
    return cut(body, BRepPrimAPI_MakeCylinder(axis_at(-40, 0, 30, gp::DX()), 6, 80).Shape());
}

// A sphere cut by a box corner and pierced near its pole (trims around the singular point).
TopoDS_Shape sphere_cut_near_pole() {
    TopoDS_Shape ball = BRepPrimAPI_MakeSphere(25).Shape();
    ball = cut(ball, BRepPrimAPI_MakeBox(gp_Pnt(5, 5, -40), 40, 40, 80).Shape());
    return cut(ball, BRepPrimAPI_MakeCylinder(axis_at(3, 0, 10), 4, 30).Shape());
}

// A torus with a slab removed: toroidal faces trimmed by planes across both seams.
TopoDS_Shape torus_sliced() {
    TopoDS_Shape ring = BRepPrimAPI_MakeTorus(40, 10).Shape();
    return cut(ring, BRepPrimAPI_MakeBox(gp_Pnt(-60, -5, -20), 120, 10, 40).Shape());
}

// A full cone with its apex, pierced off-axis.
TopoDS_Shape cone_with_apex() {
    TopoDS_Shape cone = BRepPrimAPI_MakeCone(30, 0, 50).Shape();
    return cut(cone, BRepPrimAPI_MakeCylinder(axis_at(-40, 8, 15, gp::DX()), 4, 80).Shape());
}

// Two perpendicular cylinders fused (saddle intersection curves), edges chamfered.
TopoDS_Shape crossed_cylinders() {
    TopoDS_Shape a = BRepPrimAPI_MakeCylinder(axis_at(0, 0, -40), 15, 80).Shape();
    TopoDS_Shape b = BRepPrimAPI_MakeCylinder(axis_at(-40, 0, 0, gp::DX()), 10, 80).Shape();
    return fuse(a, b);
}

// A vase: a B-spline profile revolved a full turn, with a slot cut through its wall.
TopoDS_Shape revolved_spline() {
    Handle(Geom_BSplineCurve) profile = spline_through(
        {gp_Pnt(10, 0, 0), gp_Pnt(25, 0, 15), gp_Pnt(15, 0, 35), gp_Pnt(20, 0, 55), gp_Pnt(8, 0, 70)});
    TopoDS_Edge side = BRepBuilderAPI_MakeEdge(profile);
    TopoDS_Edge top = BRepBuilderAPI_MakeEdge(gp_Pnt(8, 0, 70), gp_Pnt(0, 0, 70));
    TopoDS_Edge axis = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 70), gp_Pnt(0, 0, 0));
    TopoDS_Edge bottom = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 0), gp_Pnt(10, 0, 0));
    TopoDS_Face section = BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakeWire(side, top, axis, bottom).Wire());
    TopoDS_Shape vase = BRepPrimAPI_MakeRevol(section, gp_Ax1(gp::Origin(), gp::DZ())).Shape();
    return cut(vase, BRepPrimAPI_MakeBox(gp_Pnt(-2, -40, 20), 4, 80, 25).Shape());
}

// A closed periodic B-spline outline extruded 20 (linear extrusion faces) with a hole.
TopoDS_Shape extruded_spline() {
    Handle(TColgp_HArray1OfPnt) points = new TColgp_HArray1OfPnt(1, 12);
    for (int i = 0; i < 12; ++i) {
        double a = 2 * M_PI * i / 12, r = (i % 2 == 0) ? 40 : 28;
        points->SetValue(i + 1, gp_Pnt(r * std::cos(a), r * std::sin(a), 0));
    }
    GeomAPI_Interpolate interpolate(points, true, 1e-7);
    interpolate.Perform();
    TopoDS_Edge outline = BRepBuilderAPI_MakeEdge(interpolate.Curve());
    TopoDS_Face face = BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakeWire(outline).Wire());
    TopoDS_Shape body = BRepPrimAPI_MakePrism(face, gp_Vec(0, 0, 20)).Shape();
    return cut(body, BRepPrimAPI_MakeCylinder(axis_at(0, 0, -5), 10, 30).Shape());
}

// A loft from a circle to a rotated square (ruled B-spline sides).
TopoDS_Shape loft_circle_to_square() {
    BRepOffsetAPI_ThruSections loft(true, false);
    loft.AddWire(circle_wire(axis_at(0, 0, 0), 20));
    BRepBuilderAPI_MakeWire square;
    gp_Pnt c[4] = {gp_Pnt(15, 0, 40), gp_Pnt(0, 15, 40), gp_Pnt(-15, 0, 40), gp_Pnt(0, -15, 40)};
    for (int i = 0; i < 4; ++i) square.Add(BRepBuilderAPI_MakeEdge(c[i], c[(i + 1) % 4]));
    loft.AddWire(square.Wire());
    return loft.Shape();
}

// A tube: a circle swept along a B-spline path (pipe surface), hollowed.
TopoDS_Shape swept_tube() {
    Handle(Geom_BSplineCurve) path =
        spline_through({gp_Pnt(0, 0, 0), gp_Pnt(0, 0, 30), gp_Pnt(20, 10, 60), gp_Pnt(50, 10, 70)});
    TopoDS_Wire spine = BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(path)).Wire();
    TopoDS_Face disc = BRepBuilderAPI_MakeFace(circle_wire(axis_at(0, 0, 0), 6));
    TopoDS_Shape tube = BRepOffsetAPI_MakePipe(spine, disc).Shape();
    return cut(tube, BRepPrimAPI_MakeCylinder(axis_at(-20, 0, 15, gp::DX()), 3, 40).Shape());
}

// A box with rounded vertical edges shelled to 2 mm walls with its top face open
// (offset faces: planes and cylinders of the inner wall).
TopoDS_Shape shelled_box() {
    TopoDS_Shape box = BRepPrimAPI_MakeBox(60, 40, 30).Shape();
    BRepFilletAPI_MakeFillet round(box);
    TopoDS_Face top;
    for (TopExp_Explorer e(box, TopAbs_EDGE); e.More(); e.Next()) {
        const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
        TopoDS_Vertex a, b;
        TopExp::Vertices(edge, a, b);
        if (std::fabs(BRep_Tool::Pnt(a).Z() - BRep_Tool::Pnt(b).Z()) > 1) round.Add(5.0, edge);
    }
    TopoDS_Shape rounded = round.Shape();
    double best = -1e9;
    for (TopExp_Explorer e(rounded, TopAbs_FACE); e.More(); e.Next()) {
        TopoDS_Face f = TopoDS::Face(e.Current());
        double z = 1e9;
        for (TopExp_Explorer v(f, TopAbs_VERTEX); v.More(); v.Next())
            z = std::min(z, BRep_Tool::Pnt(TopoDS::Vertex(v.Current())).Z());
        if (z > best) best = z, top = f;
    }
    TopTools_ListOfShape open;
    open.Append(top);
    BRepOffsetAPI_MakeThickSolid shell;
    shell.MakeThickSolidByJoin(rounded, open, -2.0, 1e-3);
    return shell.Shape();
}

// A box with chamfered edges and a blind pocket whose floor edges are filleted.
TopoDS_Shape chamfered_pocket() {
    TopoDS_Shape box = BRepPrimAPI_MakeBox(80, 50, 25).Shape();
    BRepFilletAPI_MakeChamfer chamfer(box);
    TopTools_IndexedMapOfShape edges;
    TopExp::MapShapes(box, TopAbs_EDGE, edges);
    for (int i = 1; i <= edges.Extent(); ++i) chamfer.Add(1.5, TopoDS::Edge(edges(i)));
    TopoDS_Shape body = chamfer.Shape();
    TopoDS_Shape pocket = fillet_all(BRepPrimAPI_MakeBox(gp_Pnt(15, 10, 10), 50, 30, 30).Shape(), 3.0);
    return cut(body, pocket);
}

// A thin rib: a box with a slot 0.5 wide (thin planar faces beside wide ones).
TopoDS_Shape thin_slot() {
    TopoDS_Shape box = BRepPrimAPI_MakeBox(100, 40, 20).Shape();
    return cut(box, BRepPrimAPI_MakeBox(gp_Pnt(10, 19.75, -5), 80, 0.5, 30).Shape());
}

// A sphere pierced by six small holes around its axis and rotated off the axes.
TopoDS_Shape perforated_ball() {
    TopoDS_Shape ball = BRepPrimAPI_MakeSphere(30).Shape();
    for (int i = 0; i < 6; ++i) {
        double a = M_PI * i / 3;
        gp_Dir d(std::cos(a), std::sin(a), 0.6);
        ball = cut(ball, BRepPrimAPI_MakeCylinder(gp_Ax2(gp::Origin(), d), 3, 40).Shape());
    }
    return rotated(ball, gp_Ax1(gp::Origin(), gp_Dir(1, 1, 0)), 0.7);
}

// Round 2 (2026-12-02): more seams, poles and blends.

// A sphere pierced along its axis through both poles (the holes contain the poles)
// and once more off the axis.
TopoDS_Shape sphere_holes_at_poles() {
    TopoDS_Shape ball = BRepPrimAPI_MakeSphere(25).Shape();
    ball = cut(ball, BRepPrimAPI_MakeCylinder(axis_at(0, 0, -40), 5, 80).Shape());
    return cut(ball, BRepPrimAPI_MakeCylinder(axis_at(0, -40, 8, gp::DY()), 3, 80).Shape());
}

// A torus pierced where both of its seams meet (u = 0, v = 0: the point (R + r, 0, 0)).
TopoDS_Shape torus_hole_on_seams() {
    TopoDS_Shape ring = BRepPrimAPI_MakeTorus(40, 12).Shape();
    return cut(ring, BRepPrimAPI_MakeCylinder(axis_at(30, 0, 0, gp::DX()), 4, 40).Shape());
}

// A profile with an arc revolved 270 degrees (open sweep: planar end faces).
TopoDS_Shape partial_revolution() {
    TopoDS_Edge bottom = BRepBuilderAPI_MakeEdge(gp_Pnt(10, 0, 0), gp_Pnt(30, 0, 0));
    TopoDS_Edge outer = BRepBuilderAPI_MakeEdge(gp_Pnt(30, 0, 0), gp_Pnt(30, 0, 20));
    Handle(Geom_BSplineCurve) top_curve = spline_through({gp_Pnt(30, 0, 20), gp_Pnt(20, 0, 28), gp_Pnt(10, 0, 20)});
    TopoDS_Edge top = BRepBuilderAPI_MakeEdge(top_curve);
    TopoDS_Edge inner = BRepBuilderAPI_MakeEdge(gp_Pnt(10, 0, 20), gp_Pnt(10, 0, 0));
    TopoDS_Face section = BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakeWire(bottom, outer, top, inner).Wire());
    return BRepPrimAPI_MakeRevol(section, gp_Ax1(gp::Origin(), gp::DZ()), 1.5 * M_PI).Shape();
}

// A wavy B-spline plate (a prism of a B-spline face) with two holes.
TopoDS_Shape bspline_plate_with_holes() {
    TColgp_Array2OfPnt grid(1, 5, 1, 4);
    for (int i = 1; i <= 5; ++i)
        for (int j = 1; j <= 4; ++j)
            grid.SetValue(i, j, gp_Pnt(25.0 * (i - 1), 20.0 * (j - 1), 6 * std::sin(i * 1.3) * std::cos(j * 0.9)));
    Handle(Geom_BSplineSurface) wave = GeomAPI_PointsToBSplineSurface(grid).Surface();
    TopoDS_Face face = BRepBuilderAPI_MakeFace(wave, 1e-6);
    TopoDS_Shape plate = BRepPrimAPI_MakePrism(face, gp_Vec(0, 0, 8)).Shape();
    plate = cut(plate, BRepPrimAPI_MakeCylinder(axis_at(30, 30, -30), 6, 60).Shape());
    return cut(plate, BRepPrimAPI_MakeCylinder(axis_at(70, 25, -30), 4, 60).Shape());
}

// A block whose two through holes have filleted rims (tori meeting planes and cylinders).
TopoDS_Shape filleted_holes_block() {
    TopoDS_Shape block = BRepPrimAPI_MakeBox(80, 40, 20).Shape();
    block = cut(block, BRepPrimAPI_MakeCylinder(axis_at(20, 20, -5), 8, 30).Shape());
    block = cut(block, BRepPrimAPI_MakeCylinder(axis_at(60, 20, -5), 6, 30).Shape());
    BRepFilletAPI_MakeFillet round(block);
    for (TopExp_Explorer e(block, TopAbs_EDGE); e.More(); e.Next()) {
        BRepAdaptor_Curve c(TopoDS::Edge(e.Current()));
        if (c.GetType() == GeomAbs_Circle) round.Add(2.0, TopoDS::Edge(e.Current()));
    }
    return round.Shape();
}

// A rounded box offset outwards by 3 (offset surfaces of planes, cylinders and spheres).
TopoDS_Shape offset_body() {
    TopoDS_Shape box = fillet_all(BRepPrimAPI_MakeBox(50, 30, 20).Shape(), 4.0);
    BRepOffsetAPI_MakeOffsetShape offset;
    offset.PerformByJoin(box, 3.0, 1e-4);
    return offset.Shape();
}

// A sphere stretched to an ellipsoid (a general transform: B-spline faces with poles),
// pierced off its axis.
TopoDS_Shape pierced_ellipsoid() {
    gp_GTrsf stretch;
    stretch.SetValue(1, 1, 1.6);
    stretch.SetValue(2, 2, 1.0);
    stretch.SetValue(3, 3, 0.7);
    TopoDS_Shape ellipsoid = BRepBuilderAPI_GTransform(BRepPrimAPI_MakeSphere(20).Shape(), stretch, true).Shape();
    return cut(ellipsoid, BRepPrimAPI_MakeCylinder(axis_at(10, 0, -30), 4, 60).Shape());
}

// A truncated cone with a cross hole through its seam.
TopoDS_Shape frustum_hole_on_seam() {
    TopoDS_Shape frustum = BRepPrimAPI_MakeCone(25, 12, 40).Shape();
    return cut(frustum, BRepPrimAPI_MakeCylinder(axis_at(-40, 0, 20, gp::DX()), 5, 80).Shape());
}

// Round 3 (2026-12-02): sweeps along helices, drafts, an elliptic extrusion, a
// revolution that closes on its axis, variable fillets.

// A thread-like coil: a small circle swept along three turns of a helix.
TopoDS_Shape coil() {
    Handle(Geom_CylindricalSurface) cyl = new Geom_CylindricalSurface(gp_Ax3(gp::XOY()), 15);
    Handle(Geom2d_Line) line = new Geom2d_Line(gp_Pnt2d(0, 0), gp_Dir2d(2 * M_PI, 8));
    const double length = 3 * std::sqrt(4 * M_PI * M_PI + 64);
    TopoDS_Edge helix = BRepBuilderAPI_MakeEdge(line, cyl, 0, length);
    BRepLib::BuildCurves3d(helix);
    TopoDS_Wire spine = BRepBuilderAPI_MakeWire(helix).Wire();
    gp_Pnt start;
    gp_Vec tangent;
    BRepAdaptor_Curve c(helix);
    c.D1(c.FirstParameter(), start, tangent);
    BRepOffsetAPI_MakePipeShell sweep(spine);
    sweep.SetMode(gp_Dir(0, 0, 1));
    sweep.Add(BRepBuilderAPI_MakeWire(BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(start, gp_Dir(tangent)), 2))).Wire());
    sweep.Build();
    sweep.MakeSolid();
    return sweep.Shape();
}

// A revolution whose profile closes on the axis at both ends (poles on a surface of
// revolution of a B-spline), with a cross hole.
TopoDS_Shape revolved_onto_axis() {
    Handle(Geom_BSplineCurve) profile =
        spline_through({gp_Pnt(0, 0, 0), gp_Pnt(12, 0, 8), gp_Pnt(16, 0, 25), gp_Pnt(9, 0, 40), gp_Pnt(0, 0, 46)});
    TopoDS_Edge side = BRepBuilderAPI_MakeEdge(profile);
    TopoDS_Edge axis = BRepBuilderAPI_MakeEdge(gp_Pnt(0, 0, 46), gp_Pnt(0, 0, 0));
    TopoDS_Face section = BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakeWire(side, axis).Wire());
    TopoDS_Shape body = BRepPrimAPI_MakeRevol(section, gp_Ax1(gp::Origin(), gp::DZ())).Shape();
    return cut(body, BRepPrimAPI_MakeCylinder(axis_at(-30, 0, 22, gp::DX()), 3, 60).Shape());
}

// An elliptic cylinder (linear extrusion of an ellipse) with a slot across its seam.
TopoDS_Shape elliptic_extrusion() {
    TopoDS_Edge ellipse = BRepBuilderAPI_MakeEdge(gp_Elips(gp_Ax2(gp::Origin(), gp::DZ()), 30, 12));
    TopoDS_Face base = BRepBuilderAPI_MakeFace(BRepBuilderAPI_MakeWire(ellipse).Wire());
    TopoDS_Shape body = BRepPrimAPI_MakePrism(base, gp_Vec(0, 0, 25)).Shape();
    return cut(body, BRepPrimAPI_MakeBox(gp_Pnt(20, -2, 8), 20, 4, 9).Shape());
}

// A box whose top edges get a variable-radius fillet (1 to 5 along each edge).
TopoDS_Shape variable_fillet_box() {
    TopoDS_Shape box = BRepPrimAPI_MakeBox(60, 40, 30).Shape();
    BRepFilletAPI_MakeFillet round(box);
    for (TopExp_Explorer e(box, TopAbs_EDGE); e.More(); e.Next()) {
        const TopoDS_Edge& edge = TopoDS::Edge(e.Current());
        TopoDS_Vertex a, b;
        TopExp::Vertices(edge, a, b);
        if (BRep_Tool::Pnt(a).Z() > 29 && BRep_Tool::Pnt(b).Z() > 29) round.Add(1.0, 5.0, edge);
    }
    return round.Shape();
}

// ---- Round 4 (2026-12-02 evening): scale, placement and the shapes of turned and
// welded parts ---------------------------------------------------------------------

TopoDS_Shape transformed(const TopoDS_Shape& s, const gp_Trsf& t) { return BRepBuilderAPI_Transform(s, t, true).Shape(); }

// A sphere with a cylindrical boss along +X: the boss's rim crosses the sphere's seam
// (the half plane y = 0, x > 0), and a hole down the boss's axis.
TopoDS_Shape boss_on_sphere() {
    TopoDS_Shape body = fuse(BRepPrimAPI_MakeSphere(30).Shape(),
                             BRepPrimAPI_MakeCylinder(axis_at(0, 0, 0, gp::DX()), 9, 45).Shape());
    return cut(body, BRepPrimAPI_MakeCylinder(axis_at(10, 0, 0, gp::DX()), 4, 50).Shape());
}

// A pipe elbow: a quarter torus between two straight cylinders, with a hole through the bend.
TopoDS_Shape pipe_elbow() {
    const double R = 40, r = 10;
    TopoDS_Shape bend = BRepPrimAPI_MakeTorus(gp_Ax2(gp::Origin(), gp::DZ()), R, r, M_PI / 2).Shape();
    TopoDS_Shape a = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(R, 0, 0), -gp::DY()), r, 30).Shape();
    TopoDS_Shape b = BRepPrimAPI_MakeCylinder(gp_Ax2(gp_Pnt(0, R, 0), -gp::DX()), r, 30).Shape();
    TopoDS_Shape body = fuse(fuse(bend, a), b);
    const double c = R / std::sqrt(2.0);
    return cut(body, BRepPrimAPI_MakeCylinder(axis_at(c, c, -20), 3, 40).Shape());
}

// A plate with a 6 x 6 grid of holes and three half holes cut into its sides (notches
// that make the outer loop concave).
TopoDS_Shape holes_grid_plate() {
    TopoDS_Shape plate = BRepPrimAPI_MakeBox(100, 100, 5).Shape();
    for (int i = 0; i < 6; ++i)
        for (int j = 0; j < 6; ++j)
            plate = cut(plate, BRepPrimAPI_MakeCylinder(axis_at(15 + 14 * i, 15 + 14 * j, -1), 2.5 + 0.3 * ((i + j) % 3), 7).Shape());
    plate = cut(plate, BRepPrimAPI_MakeCylinder(axis_at(0, 50, -1), 6, 7).Shape());
    plate = cut(plate, BRepPrimAPI_MakeCylinder(axis_at(50, 100, -1), 6, 7).Shape());
    return cut(plate, BRepPrimAPI_MakeCylinder(axis_at(100, 30, -1), 4, 7).Shape());
}

// A turned shaft: a profile of lines, a groove arc and chamfers revolved a full turn
// (planes, cylinders, cones and a torus on one axis, their seams on one half plane), with a
// cross hole and a flat milled across the seam.
TopoDS_Shape turned_shaft() {
    std::vector<gp_Pnt> p = {gp_Pnt(0, 0, 0),   gp_Pnt(8, 0, 0),   gp_Pnt(10, 0, 2),  gp_Pnt(10, 0, 30),
                             gp_Pnt(14, 0, 34), gp_Pnt(14, 0, 60), gp_Pnt(6, 0, 80), gp_Pnt(0, 0, 80)};
    BRepBuilderAPI_MakeWire wire;
    for (size_t k = 0; k + 1 < p.size(); ++k) wire.Add(BRepBuilderAPI_MakeEdge(p[k], p[k + 1]).Edge());
    wire.Add(BRepBuilderAPI_MakeEdge(p.back(), p.front()).Edge());
    TopoDS_Shape body = BRepPrimAPI_MakeRevol(BRepBuilderAPI_MakeFace(wire.Wire()), gp_Ax1(gp::Origin(), gp::DZ())).Shape();
    // A round groove (a torus) at z = 45.
    body = cut(body, BRepPrimAPI_MakeTorus(gp_Ax2(gp_Pnt(0, 0, 45), gp::DZ()), 14, 2.5).Shape());
    body = cut(body, BRepPrimAPI_MakeCylinder(axis_at(-20, 0, 15, gp::DX()), 2.5, 40).Shape());
    return cut(body, BRepPrimAPI_MakeBox(gp_Pnt(11, -20, 38), 10, 40, 16).Shape());
}

// Two cylinders of equal radius meeting at right angles (a tee): their intersection
// curves meet at two points where the faces' trims touch.
TopoDS_Shape equal_tee() {
    TopoDS_Shape a = BRepPrimAPI_MakeCylinder(axis_at(0, 0, -40), 12, 80).Shape();
    TopoDS_Shape b = BRepPrimAPI_MakeCylinder(axis_at(0, 0, 0, gp::DX()), 12, 40).Shape();
    return fuse(a, b);
}

// A tube with a stadium slot (two half circles and two lines) cut through its wall across
// the seam, and a cone-tipped end.
TopoDS_Shape slotted_tube() {
    TopoDS_Shape tube = cut(BRepPrimAPI_MakeCylinder(axis_at(0, 0, 0), 15, 70).Shape(),
                            BRepPrimAPI_MakeCylinder(axis_at(0, 0, -1), 11, 72).Shape());
    TopoDS_Shape slot = fuse(fuse(BRepPrimAPI_MakeCylinder(axis_at(0, 0, 25, gp::DX()), 4, 30).Shape(),
                                  BRepPrimAPI_MakeCylinder(axis_at(0, 0, 45, gp::DX()), 4, 30).Shape()),
                             BRepPrimAPI_MakeBox(gp_Pnt(0, -4, 25), 30, 8, 20).Shape());
    tube = cut(tube, slot);
    return fuse(tube, BRepPrimAPI_MakeCone(axis_at(0, 0, 70), 15, 5, 12).Shape());
}

// A cone capped by a sphere that cuts it (a bullet), pierced across.
TopoDS_Shape bullet() {
    TopoDS_Shape cone = BRepPrimAPI_MakeCone(20, 8, 50).Shape();
    TopoDS_Shape cap = BRepPrimAPI_MakeSphere(gp_Pnt(0, 0, 45), 12).Shape();
    TopoDS_Shape body = fuse(cone, cap);
    return cut(body, BRepPrimAPI_MakeCylinder(axis_at(-30, 0, 20, gp::DX()), 3, 60).Shape());
}

// plate_with_holes and a filleted box scaled to 0.06 mm across (every length 1e-3 of the
// original): tolerances of 1e-7 mm and below.
TopoDS_Shape tiny_part() {
    gp_Trsf t;
    t.SetScale(gp::Origin(), 1e-3);
    return transformed(plate_with_holes(), t);
}

// The pipe elbow 200 times larger and 5e5 away from the origin along a tilted axis (an
// aircraft part in global coordinates).
TopoDS_Shape far_large_part() {
    gp_Trsf scale, move;
    scale.SetScale(gp::Origin(), 200);
    move.SetTransformation(gp_Ax3(gp_Pnt(5e5, -3e5, 2e5), gp_Dir(1, 1, 1), gp_Dir(1, -1, 0)), gp_Ax3());
    move.Invert();
    return transformed(pipe_elbow(), move * scale);
}

// A box whose sides get a 5 degree draft (tilted planes) with a drafted cylindrical boss
// on top (a cone from the draft).
TopoDS_Shape drafted_box() {
    TopoDS_Shape body = fuse(BRepPrimAPI_MakeBox(60, 40, 20).Shape(),
                             BRepPrimAPI_MakeCylinder(axis_at(30, 20, 20), 10, 15).Shape());
    BRepOffsetAPI_DraftAngle draft(body);
    const gp_Pln neutral(gp_Pnt(0, 0, 0), gp::DZ());
    for (TopExp_Explorer e(body, TopAbs_FACE); e.More(); e.Next()) {
        const TopoDS_Face& f = TopoDS::Face(e.Current());
        BRepAdaptor_Surface s(f);
        const bool vertical_plane = s.GetType() == GeomAbs_Plane && std::abs(s.Plane().Axis().Direction().Z()) < 1e-9;
        const bool side_cylinder = s.GetType() == GeomAbs_Cylinder;
        if (vertical_plane || side_cylinder) draft.Add(f, gp::DZ(), 5.0 * M_PI / 180.0, neutral);
    }
    draft.Build();
    return draft.Shape();
}

// A block whose top is a wavy B-spline of many spans (heights sampled on 41 x 31 points):
// its four top edges are iso-lines crossing every span (OCCT's terrain.brep), its sides
// extrusions of B-spline curves; a hole through it.
TopoDS_Shape wavy_block() {
    TColgp_Array2OfPnt grid(1, 41, 1, 31);
    for (int i = 1; i <= 41; ++i)
        for (int j = 1; j <= 31; ++j)
            grid.SetValue(i, j, gp_Pnt(2.0 * (i - 1), 2.0 * (j - 1),
                                       3 * std::sin(0.9 * i) * std::cos(0.7 * j) + 0.5 * std::sin(2.3 * i + j)));
    Handle(Geom_BSplineSurface) top = GeomAPI_PointsToBSplineSurface(grid, 3, 8, GeomAbs_C2, 1e-3).Surface();
    TopoDS_Shape block = BRepPrimAPI_MakePrism(BRepBuilderAPI_MakeFace(top, 1e-6).Face(), gp_Vec(0, 0, -15)).Shape();
    return cut(block, BRepPrimAPI_MakeCylinder(axis_at(50, 30, -40), 5, 60).Shape());
}

// A cylindrical boss fused onto the wavy block's top: its rim is an intersection curve
// on the many-span B-spline, approximated with p-curves on both faces.
TopoDS_Shape boss_on_wavy_block() {
    return fuse(wavy_block(), BRepPrimAPI_MakeCylinder(axis_at(20, 30, -5), 6, 15).Shape());
}

// A box without its top: an open shell (a surface model, no solid).
TopoDS_Shape open_box_shell() {
    const TopoDS_Shape box = fillet_all(BRepPrimAPI_MakeBox(60, 40, 30).Shape(), 3.0);
    BRep_Builder b;
    TopoDS_Shell shell;
    b.MakeShell(shell);
    for (TopExp_Explorer e(box, TopAbs_FACE); e.More(); e.Next()) {
        BRepAdaptor_Surface s(TopoDS::Face(e.Current()));
        const bool top = s.GetType() == GeomAbs_Plane && s.Plane().Location().Z() > 29.9 &&
                         std::abs(s.Plane().Axis().Direction().Z()) > 0.99;
        if (!top) b.Add(shell, e.Current());
    }
    return shell;
}

// Two solids apart in one file (a compound): a pierced sphere and a chamfered box.
TopoDS_Shape two_solids() {
    BRep_Builder b;
    TopoDS_Compound both;
    b.MakeCompound(both);
    b.Add(both, cut(BRepPrimAPI_MakeSphere(gp_Pnt(0, 0, 0), 15).Shape(),
                    BRepPrimAPI_MakeCylinder(axis_at(0, 0, -20), 4, 40).Shape()));
    TopoDS_Shape box = BRepPrimAPI_MakeBox(gp_Pnt(40, -10, -10), 30, 20, 20).Shape();
    BRepFilletAPI_MakeChamfer chamfer(box);
    for (TopExp_Explorer e(box, TopAbs_EDGE); e.More(); e.Next()) chamfer.Add(2.0, TopoDS::Edge(e.Current()));
    b.Add(both, chamfer.Shape());
    return both;
}

// A filleted box's faces moved apart by up to 2e-4 and sewn again with tolerance 1e-3
// (files from systems that export faces, not a solid): edges with tolerances ~1e-4.
TopoDS_Shape sewn_patchwork() {
    const TopoDS_Shape box = fillet_all(BRepPrimAPI_MakeBox(50, 40, 30).Shape(), 5.0);
    BRepBuilderAPI_Sewing sewing(1e-3);
    int k = 0;
    for (TopExp_Explorer e(box, TopAbs_FACE); e.More(); e.Next(), ++k) {
        gp_Trsf t;
        t.SetTranslation(gp_Vec(1e-4 * std::sin(k), 1e-4 * std::cos(1.7 * k), 1e-4 * std::sin(2.9 * k)));
        sewing.Add(transformed(e.Current(), t));
    }
    sewing.Perform();
    TopoDS_Shape sewn = sewing.SewedShape();
    for (TopExp_Explorer e(sewn, TopAbs_SHELL); e.More(); e.Next()) {
        BRep_Builder b;
        TopoDS_Solid solid;
        b.MakeSolid(solid);
        b.Add(solid, e.Current());
        return solid;
    }
    return sewn;
}

struct Part {
    const char* name;
    std::function<TopoDS_Shape()> make;
};

std::vector<Part> parts() {
    return {{"plate_with_holes", plate_with_holes},       {"cylinder_hole_on_seam", cylinder_hole_on_seam},
            {"sphere_cut_near_pole", sphere_cut_near_pole}, {"torus_sliced", torus_sliced},
            {"cone_with_apex", cone_with_apex},           {"crossed_cylinders", crossed_cylinders},
            {"revolved_spline", revolved_spline},         {"extruded_spline", extruded_spline},
            {"loft_circle_to_square", loft_circle_to_square}, {"swept_tube", swept_tube},
            {"shelled_box", shelled_box},                 {"chamfered_pocket", chamfered_pocket},
            {"thin_slot", thin_slot},                     {"perforated_ball", perforated_ball},
            {"sphere_holes_at_poles", sphere_holes_at_poles}, {"torus_hole_on_seams", torus_hole_on_seams},
            {"partial_revolution", partial_revolution},   {"bspline_plate_with_holes", bspline_plate_with_holes},
            {"filleted_holes_block", filleted_holes_block}, {"offset_body", offset_body},
            {"pierced_ellipsoid", pierced_ellipsoid},     {"frustum_hole_on_seam", frustum_hole_on_seam},
            {"coil", coil},                               {"revolved_onto_axis", revolved_onto_axis},
            {"elliptic_extrusion", elliptic_extrusion},   {"variable_fillet_box", variable_fillet_box},
            {"boss_on_sphere", boss_on_sphere},           {"pipe_elbow", pipe_elbow},
            {"holes_grid_plate", holes_grid_plate},       {"turned_shaft", turned_shaft},
            {"equal_tee", equal_tee},                     {"slotted_tube", slotted_tube},
            {"bullet", bullet},                           {"tiny_part", tiny_part},
            {"far_large_part", far_large_part},           {"drafted_box", drafted_box},
            {"wavy_block", wavy_block},                   {"boss_on_wavy_block", boss_on_wavy_block},
            {"open_box_shell", open_box_shell},           {"two_solids", two_solids},
            {"sewn_patchwork", sewn_patchwork}};
}

bool write_step(const TopoDS_Shape& s, const std::string& path) {
    STEPControl_Writer writer;
    return writer.Transfer(s, STEPControl_AsIs) == IFSelect_RetDone &&
           writer.Write(path.c_str()) == IFSelect_RetDone;
}

bool write_iges(const TopoDS_Shape& s, const std::string& path, bool brep_mode) {
    IGESControl_Controller::Init();
    IGESControl_Writer writer("MM", brep_mode ? 1 : 0);
    return writer.AddShape(s) && writer.Write(path.c_str());
}

int faces_of(const TopoDS_Shape& s) {
    int n = 0;
    for (TopExp_Explorer e(s, TopAbs_FACE); e.More(); e.Next()) ++n;
    return n;
}

void write_part(const Part& part, const std::string& dir) {
    TopoDS_Shape shape;
    try {
        shape = part.make();
    } catch (const Standard_Failure& e) {
        std::printf("%-24s modelling failed: %s\n", part.name, e.GetMessageString());
        return;
    }
    if (!BRepCheck_Analyzer(shape).IsValid()) {
        std::printf("%-24s not valid by BRepCheck_Analyzer: not written\n", part.name);
        return;
    }
    std::string base = dir + "/" + part.name;
    bool ok = write_step(shape, base + ".stp") && write_iges(shape, base + "_brep.igs", true) &&
              write_iges(shape, base + "_faces.igs", false) && BRepTools::Write(shape, (base + ".brep").c_str());
    std::printf("%-24s faces %3d  %s\n", part.name, faces_of(shape), ok ? "written" : "WRITE FAILED");
}

}  // namespace

// Each .brep file given, read by BRepTools::Read, written again as STEP and as IGES in
// both modes (real parts through the IGES and STEP writers: OCCT's own sample files).
int convert_breps(const std::string& dir, int count, char** paths) {
    int failed = 0;
    for (int k = 0; k < count; ++k) {
        TopoDS_Shape shape;
        BRep_Builder builder;
        const std::string path = paths[k];
        if (path.size() > 4 && path.substr(path.size() - 4) == ".stp") {  // a STEP file back to .brep
            STEPControl_Reader reader;
            if (reader.ReadFile(path.c_str()) == IFSelect_RetDone && reader.TransferRoots() > 0)
                BRepTools::Write(reader.OneShape(), (dir + "/" + path.substr(path.find_last_of('/') + 1) + ".brep").c_str());
            continue;
        }
        if (!BRepTools::Read(shape, path.c_str(), builder) || shape.IsNull()) {
            std::printf("%-32s not read\n", path.c_str());
            ++failed;
            continue;
        }
        std::string stem = path.substr(path.find_last_of('/') + 1);
        stem = dir + "/" + stem.substr(0, stem.find_last_of('.'));
        const bool ok = write_step(shape, stem + ".stp") && write_iges(shape, stem + "_brep.igs", true) &&
                        write_iges(shape, stem + "_faces.igs", false);
        std::printf("%-32s faces %4d  %s\n", path.c_str(), faces_of(shape), ok ? "written" : "WRITE FAILED");
        failed += !ok;
    }
    return failed > 0;
}

int main(int argc, char** argv) {
    if (argc >= 4 && std::string(argv[2]) == "--from-brep") {
        Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
        return convert_breps(argv[1], argc - 3, argv + 3);
    }
    if (argc != 2) {
        std::fprintf(stderr, "usage: occt_make_corpus OUT_DIR | occt_make_corpus OUT_DIR --from-brep FILE.brep...\n");
        return 2;
    }
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    for (const Part& part : parts()) write_part(part, argv[1]);
    // The turned shaft once more as STEP in inches (lengths divided by 25.4 in the file).
    Interface_Static::SetCVal("write.step.unit", "INCH");
    const std::string inch = std::string(argv[1]) + "/turned_shaft_inch.stp";
    std::printf("%-24s %s\n", "turned_shaft_inch", write_step(turned_shaft(), inch) ? "written" : "WRITE FAILED");
    return 0;
}
