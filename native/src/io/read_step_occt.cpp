// read_step through Open CASCADE (built only with TRIMKIT_WITH_OCCT): STEPCAFControl_Reader
// gives a TopoDS_Shape (the document's free shapes) with names and colours,
// BRepBuilderAPI_NurbsConvert turns every surface and pcurve into a B-spline, and each face
// occurrence (TopExp_Explorer, so instanced parts count once per placement) becomes a
// geom::Face with its placement applied to the control points. Edges are shared through a
// TopTools_IndexedMapOfShape (same TShape and location). OCCT's memory faults on broken
// files become read errors (OcctSignalGuard).
#include "io/read_step.h"

// OCC_CATCH_SIGNALS turns a signal raised inside OCCT into a Standard_Failure (Linux).
#define OCC_CONVERT_SIGNALS

#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <GeomAdaptor_Surface.hxx>
#include <GeomConvert.hxx>
#include <Geom2dConvert.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <OSD.hxx>
#include <Standard_ErrorHandler.hxx>
#include <BRep_Builder.hxx>
#include <Quantity_Color.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <TCollection_AsciiString.hxx>
#include <TDF_LabelSequence.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopoDS_Compound.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_ColorTool.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>
#include <gp_Trsf.hxx>

#include <csignal>
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <vector>

#include "geom/error.h"

namespace trimkit::io {

namespace {

// OCCT's default messenger prints transfer messages on stdout, which would corrupt
// `trimkit ... --json` output; drop that printer once per process.
void silence_occt_stdout() {
    static std::once_flag once;
    std::call_once(once, [] {
        Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    });
}

// The file's name for the surface before NurbsConvert (Face::surface_kind).
std::string surface_kind(const TopoDS_Face& face) {
    const Handle(Geom_Surface) s = BRep_Tool::Surface(face);
    if (s.IsNull()) return "unknown";
    switch (GeomAdaptor_Surface(s).GetType()) {
        case GeomAbs_Plane: return "plane";
        case GeomAbs_Cylinder: return "cylinder";
        case GeomAbs_Cone: return "cone";
        case GeomAbs_Sphere: return "sphere";
        case GeomAbs_Torus: return "torus";
        case GeomAbs_BezierSurface: return "bezier";
        case GeomAbs_BSplineSurface: return "bspline";
        case GeomAbs_SurfaceOfRevolution: return "revolution";
        case GeomAbs_SurfaceOfExtrusion: return "extrusion";
        case GeomAbs_OffsetSurface: return "offset";
        default: return "other";
    }
}

// Knots with each value repeated by its multiplicity.
template <class Get, class Mult>
std::vector<double> expanded_knots(int count, Get knot, Mult multiplicity) {
    std::vector<double> U;
    for (int i = 1; i <= count; ++i)
        for (int k = 0; k < multiplicity(i); ++k) U.push_back(knot(i));
    return U;
}

Eigen::Vector3d to_eigen(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }

// A B-spline surface (made non-periodic on a copy) with `placement` applied to its poles.
geom::NurbsSurface to_nurbs(Handle(Geom_BSplineSurface) s, const gp_Trsf& placement) {
    s = Handle(Geom_BSplineSurface)::DownCast(s->Copy());
    if (s->IsUPeriodic()) s->SetUNotPeriodic();
    if (s->IsVPeriodic()) s->SetVNotPeriodic();
    const int nu = s->NbUPoles(), nv = s->NbVPoles();
    const bool rational = s->IsURational() || s->IsVRational();
    std::vector<Eigen::Vector3d> P;
    std::vector<double> w;
    P.reserve(static_cast<size_t>(nu) * nv);
    for (int i = 1; i <= nu; ++i)
        for (int j = 1; j <= nv; ++j) {
            P.push_back(to_eigen(s->Pole(i, j).Transformed(placement)));
            if (rational) w.push_back(s->Weight(i, j));
        }
    return geom::NurbsSurface(
        s->UDegree(), s->VDegree(),
        expanded_knots(s->NbUKnots(), [&](int i) { return s->UKnot(i); },
                       [&](int i) { return s->UMultiplicity(i); }),
        expanded_knots(s->NbVKnots(), [&](int i) { return s->VKnot(i); },
                       [&](int i) { return s->VMultiplicity(i); }),
        nu, nv, std::move(P), std::move(w));
}

// Restricts `c` to [a, b] unless that is already (to rounding) its whole domain.
// A range reaching outside the domain (NurbsConvert can reparameterise a curve without
// updating the edge's range) keeps the whole curve.
template <int Dim>
geom::NurbsCurve<Dim> restricted(const geom::NurbsCurve<Dim>& c, double a, double b) {
    const auto [lo, hi] = c.domain();
    const double tol = 1e-9 * std::max(1.0, hi - lo);
    if (a < lo - tol || b > hi + tol) return c;
    if (std::abs(a - lo) <= tol && std::abs(b - hi) <= tol) return c;
    return c.sub_curve(a, b);
}

// The pcurve of `edge` on `face` over the edge's range, as traversed (reversed for a
// REVERSED edge).
geom::NurbsCurve2d pcurve(const TopoDS_Edge& edge, const TopoDS_Face& face) {
    double first = 0, last = 0;
    const Handle(Geom2d_Curve) c = BRep_Tool::CurveOnSurface(edge, face, first, last);
    if (c.IsNull()) throw std::runtime_error("an edge has no curve on the face");
    Handle(Geom2d_BSplineCurve) b = Handle(Geom2d_BSplineCurve)::DownCast(c);
    bool trimmed = false;
    if (b.IsNull()) {
        b = Geom2dConvert::CurveToBSplineCurve(new Geom2d_TrimmedCurve(c, first, last));
        trimmed = true;
    } else {
        b = Handle(Geom2d_BSplineCurve)::DownCast(b->Copy());
        if (b->IsPeriodic()) b->SetNotPeriodic();
    }
    std::vector<Eigen::Vector2d> P;
    std::vector<double> w;
    for (int i = 1; i <= b->NbPoles(); ++i) {
        P.emplace_back(b->Pole(i).X(), b->Pole(i).Y());
        if (b->IsRational()) w.push_back(b->Weight(i));
    }
    geom::NurbsCurve2d curve(b->Degree(),
                             expanded_knots(b->NbKnots(), [&](int i) { return b->Knot(i); },
                                            [&](int i) { return b->Multiplicity(i); }),
                             std::move(P), std::move(w));
    if (!trimmed) curve = restricted(curve, first, last);
    return edge.Orientation() == TopAbs_REVERSED ? curve.reversed() : curve;
}

// The model-space edge: its 3D curve (placed) where it has one, and its end vertices.
geom::Edge model_edge(const TopoDS_Edge& located) {
    const TopoDS_Edge edge = TopoDS::Edge(located.Oriented(TopAbs_FORWARD));
    geom::Edge out;
    TopoDS_Vertex v0, v1;
    TopExp::Vertices(edge, v0, v1);
    if (!v0.IsNull()) out.start = to_eigen(BRep_Tool::Pnt(v0));
    if (!v1.IsNull()) out.end = to_eigen(BRep_Tool::Pnt(v1));
    if (BRep_Tool::Degenerated(edge)) return out;
    TopLoc_Location loc;
    double first = 0, last = 0;
    const Handle(Geom_Curve) c = BRep_Tool::Curve(edge, loc, first, last);
    if (c.IsNull()) return out;
    try {
        Handle(Geom_BSplineCurve) b = Handle(Geom_BSplineCurve)::DownCast(c);
        bool trimmed = false;
        if (b.IsNull()) {
            b = GeomConvert::CurveToBSplineCurve(new Geom_TrimmedCurve(c, first, last));
            trimmed = true;
        } else {
            b = Handle(Geom_BSplineCurve)::DownCast(b->Copy());
            if (b->IsPeriodic()) b->SetNotPeriodic();
        }
        const gp_Trsf placement = loc.Transformation();
        std::vector<Eigen::Vector3d> P;
        std::vector<double> w;
        for (int i = 1; i <= b->NbPoles(); ++i) {
            P.push_back(to_eigen(b->Pole(i).Transformed(placement)));
            if (b->IsRational()) w.push_back(b->Weight(i));
        }
        geom::NurbsCurve3d curve(b->Degree(),
                                 expanded_knots(b->NbKnots(), [&](int i) { return b->Knot(i); },
                                                [&](int i) { return b->Multiplicity(i); }),
                                 std::move(P), std::move(w));
        out.curve = trimmed ? curve : restricted(curve, first, last);
    } catch (const Standard_Failure&) {
        // No usable 3D curve: the coedges still carry the pcurves.
    } catch (const std::exception&) {
    }
    return out;
}

// Shifts every pcurve of `face` by whole periods so the loops lie in the surface's
// domain (a periodic surface made non-periodic keeps only its first period).
void shift_into_domain(geom::Face& face, double period_u, double period_v) {
    Eigen::AlignedBox2d box;
    for (const auto& loop : face.loops)
        for (const auto& c : loop.coedges) box.extend(c.curve.control_box());
    const auto [u0, u1] = face.surface.domain_u();
    const auto [v0, v1] = face.surface.domain_v();
    Eigen::Vector2d shift(0, 0);
    const double mid_u = 0.5 * (box.min().x() + box.max().x());
    const double mid_v = 0.5 * (box.min().y() + box.max().y());
    if (period_u > 0 && (mid_u < u0 || mid_u > u1))
        shift.x() = -std::floor((mid_u - u0) / period_u) * period_u;
    if (period_v > 0 && (mid_v < v0 || mid_v > v1))
        shift.y() = -std::floor((mid_v - v0) / period_v) * period_v;
    if (shift.isZero()) return;
    Eigen::Transform<double, 2, Eigen::Affine> T = Eigen::Transform<double, 2, Eigen::Affine>::Identity();
    T.translate(shift);
    for (auto& loop : face.loops)
        for (auto& c : loop.coedges) c.curve = c.curve.transformed(T);
}

// The wires of `face`, the outer one (BRepTools::OuterWire) first.
std::vector<TopoDS_Wire> ordered_wires(const TopoDS_Face& face) {
    const TopoDS_Wire outer = BRepTools::OuterWire(face);
    std::vector<TopoDS_Wire> wires;
    if (!outer.IsNull()) wires.push_back(outer);
    for (TopExp_Explorer it(face, TopAbs_WIRE); it.More(); it.Next())
        if (outer.IsNull() || !it.Current().IsSame(outer)) wires.push_back(TopoDS::Wire(it.Current()));
    return wires;
}

// One face occurrence to a geom::Face. Throws (OCCT or trimkit exceptions) on failure.
geom::Face convert_face(const TopoDS_Face& located, const TopoDS_Face& original,
                        const TopTools_IndexedMapOfShape& edges) {
    geom::Face out;
    out.reversed = located.Orientation() == TopAbs_REVERSED;
    out.surface_kind = original.IsNull() ? "bspline" : surface_kind(original);
    // Loops are read from the forward face, so the outer loop runs counter-clockwise.
    const TopoDS_Face face = TopoDS::Face(located.Oriented(TopAbs_FORWARD));

    TopLoc_Location loc;
    const Handle(Geom_Surface) s = BRep_Tool::Surface(face, loc);
    if (s.IsNull()) throw std::runtime_error("no surface");
    Handle(Geom_BSplineSurface) b = Handle(Geom_BSplineSurface)::DownCast(s);
    if (b.IsNull()) b = GeomConvert::SurfaceToBSplineSurface(s);
    const double period_u = b->IsUPeriodic() ? b->UPeriod() : 0;
    const double period_v = b->IsVPeriodic() ? b->VPeriod() : 0;
    out.surface = to_nurbs(b, loc.Transformation());

    const TopoDS_Wire outer = BRepTools::OuterWire(face);
    for (const TopoDS_Wire& wire : ordered_wires(face)) {
        geom::Loop loop;
        loop.outer = !outer.IsNull() && wire.IsSame(outer);
        for (BRepTools_WireExplorer it(wire, face); it.More(); it.Next()) {
            const TopoDS_Edge& edge = it.Current();
            geom::Coedge coedge;
            coedge.curve = pcurve(edge, face);
            coedge.edge = edges.FindIndex(edge) - 1;
            coedge.edge_reversed = edge.Orientation() == TopAbs_REVERSED;
            loop.coedges.push_back(std::move(coedge));
        }
        if (!loop.coedges.empty()) out.loops.push_back(std::move(loop));
    }
    if (out.loops.empty()) {
        out.loops.push_back(geom::natural_boundary_loop(out.surface));
    } else {
        shift_into_domain(out, period_u, period_v);
    }
    return out;
}

// The largest gap between the end of a coedge and the start of the next, relative to
// the size of the face's domain.
double loop_gap(const geom::Face& face) {
    const auto [u0, u1] = face.surface.domain_u();
    const auto [v0, v1] = face.surface.domain_v();
    double gap = 0;
    for (const auto& loop : face.loops)
        for (size_t k = 0; k < loop.coedges.size(); ++k) {
            const auto& a = loop.coedges[k].curve;
            const auto& b = loop.coedges[(k + 1) % loop.coedges.size()].curve;
            gap = std::max(gap, (a.evaluate(a.domain().second) - b.evaluate(b.domain().first)).norm());
        }
    return gap / std::max(u1 - u0, v1 - v0);
}

// Relative loop gaps: above kLoopGapRetry the face is converted again on its own (the
// better result is kept); above kLoopGapMax it is skipped.
constexpr double kLoopGapRetry = 1e-6;
constexpr double kLoopGapMax = 1e-4;

// The edge indices of a face's coedges, loop by loop, in convert_face's order.
std::vector<std::vector<int>> coedge_edges(const TopoDS_Face& located,
                                           const TopTools_IndexedMapOfShape& edges) {
    const TopoDS_Face face = TopoDS::Face(located.Oriented(TopAbs_FORWARD));
    std::vector<std::vector<int>> ids;
    for (const TopoDS_Wire& wire : ordered_wires(face)) {
        std::vector<int> loop;
        for (BRepTools_WireExplorer it(wire, face); it.More(); it.Next())
            loop.push_back(edges.FindIndex(it.Current()) - 1);
        if (!loop.empty()) ids.push_back(std::move(loop));
    }
    return ids;
}

// `original` converted on its own, for faces whose pcurves came out of the whole-shape
// NurbsConvert inconsistent (seen in ec_turbine-A.stp); coedges keep the shared edge
// indices of the original face's edges (`original_edges` indexes like Model::edges).
geom::Face convert_face_alone(const TopoDS_Face& original,
                              const TopTools_IndexedMapOfShape& original_edges) {
    const TopoDS_Face alone = TopoDS::Face(BRepBuilderAPI_NurbsConvert(original, true).Shape());
    TopTools_IndexedMapOfShape none;
    geom::Face out = convert_face(alone, original, none);
    const auto ids = coedge_edges(original, original_edges);
    if (ids.empty()) return out;  // natural boundary
    if (ids.size() != out.loops.size())
        throw std::runtime_error("face conversion changed its loops");
    for (size_t l = 0; l < ids.size(); ++l) {
        if (ids[l].size() != out.loops[l].coedges.size())
            throw std::runtime_error("face conversion changed its loops");
        for (size_t k = 0; k < ids[l].size(); ++k) out.loops[l].coedges[k].edge = ids[l][k];
    }
    return out;
}

std::string failure_text(const Standard_Failure& e) {
    const char* text = e.GetMessageString();
    return std::string(e.DynamicType()->Name()) + (text && *text ? std::string(": ") + text : "");
}

// While OCCT reads a file, its signal handlers are installed so that a memory fault
// inside it (OCCT 7.6 dereferences null handles for some broken references, e.g. an
// entity whose type name is damaged) jumps to OCC_CATCH_SIGNALS and is thrown as a
// Standard_Failure instead of killing the process, Blender included. The process's own
// handlers are restored afterwards.
class OcctSignalGuard {
public:
    OcctSignalGuard() {
        for (int s = 1; s < NSIG; ++s) sigaction(s, nullptr, &saved_[s]);
        OSD::SetSignal(OSD_SignalMode_Set, /*theFloatingSignal=*/false);
    }
    ~OcctSignalGuard() {
        for (int s = 1; s < NSIG; ++s)
            if (s != SIGKILL && s != SIGSTOP) sigaction(s, &saved_[s], nullptr);
    }
    OcctSignalGuard(const OcctSignalGuard&) = delete;
    OcctSignalGuard& operator=(const OcctSignalGuard&) = delete;

private:
    struct sigaction saved_[NSIG] = {};
};

// Names and colours of the document's shapes (XCAF), turned into Model::colors.
class StepStyles {
public:
    explicit StepStyles(const Handle(TDocStd_Document)& doc)
        : shapes_(XCAFDoc_DocumentTool::ShapeTool(doc->Main())),
          colors_(XCAFDoc_DocumentTool::ColorTool(doc->Main())) {}

    // The free shapes as one shape (a compound when there are several).
    TopoDS_Shape root() const {
        TDF_LabelSequence labels;
        shapes_->GetFreeShapes(labels);
        if (labels.Length() == 1) return shapes_->GetShape(labels.Value(1));
        TopoDS_Compound all;
        BRep_Builder builder;
        builder.MakeCompound(all);
        for (int i = 1; i <= labels.Length(); ++i) builder.Add(all, shapes_->GetShape(labels.Value(i)));
        return all;
    }

    // The name of the shape's label (an instance's own name, else its part's); "" if none.
    std::string name(const TopoDS_Shape& shape) const {
        TDF_Label label;
        if (!shapes_->Search(shape, label)) return {};
        std::string own = label_name(label);
        TDF_Label part;
        if (own.empty() && XCAFDoc_ShapeTool::GetReferredShape(label, part)) own = label_name(part);
        return own;
    }

    // Index into model.colors of the shape's surface (or generic) colour, -1 if none;
    // equal colours share one entry.
    int color(const TopoDS_Shape& shape, geom::Model& model) {
        Quantity_Color c;
        if (!colors_->GetColor(shape, XCAFDoc_ColorSurf, c) && !colors_->GetColor(shape, XCAFDoc_ColorGen, c))
            return -1;
        double r = 0, g = 0, b = 0;
        c.Values(r, g, b, Quantity_TOC_sRGB);  // the file's own numbers
        const std::array<double, 3> rgb{r, g, b};
        const auto found = index_.find(rgb);
        if (found != index_.end()) return found->second;
        geom::Color color;
        color.rgb = rgb;
        model.colors.push_back(color);
        return index_[rgb] = static_cast<int>(model.colors.size()) - 1;
    }

private:
    static std::string label_name(const TDF_Label& label) {
        Handle(TDataStd_Name) name;
        if (!label.FindAttribute(TDataStd_Name::GetID(), name)) return {};
        return TCollection_AsciiString(name->Get()).ToCString();  // UTF-8
    }

    Handle(XCAFDoc_ShapeTool) shapes_;
    Handle(XCAFDoc_ColorTool) colors_;
    std::map<std::array<double, 3>, int> index_;
};

}  // namespace

bool step_supported() { return true; }

geom::Model read_step_unguarded(const std::string& path);

geom::Model read_step(const std::string& path) {
    silence_occt_stdout();
    try {
        OcctSignalGuard guard;
        OCC_CATCH_SIGNALS
        return read_step_unguarded(path);
    } catch (const Standard_Failure& e) {
        throw geom::ReadError(path, 0, "Open CASCADE failed (a damaged file?): " + failure_text(e));
    }
}

geom::Model read_step_unguarded(const std::string& path) {
    TopoDS_Shape original;
    TopoDS_Shape shape;
    Handle(TDocStd_Document) doc;
    try {
        XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", doc);
        STEPCAFControl_Reader reader;
        reader.SetColorMode(true);
        reader.SetNameMode(true);
        if (reader.ReadFile(path.c_str()) != IFSelect_RetDone)
            throw geom::ReadError(path, 0, "Open CASCADE cannot read this file as STEP");
        if (!reader.Transfer(doc)) throw geom::ReadError(path, 0, "Open CASCADE cannot transfer the STEP file");
        original = StepStyles(doc).root();
        if (original.IsNull()) throw geom::ReadError(path, 0, "the STEP file gives no shape");
        BRepBuilderAPI_NurbsConvert convert(original);
        shape = convert.Shape();
    } catch (const Standard_Failure& e) {
        throw geom::ReadError(path, 0, "Open CASCADE failed: " + failure_text(e));
    }
    StepStyles styles(doc);

    geom::Model model;
    model.units = "mm";  // OCCT converts lengths to xstep.cad.unit, millimetres by default
    model.scale_to_metres = 1e-3;

    TopTools_IndexedMapOfShape edge_map;
    TopExp::MapShapes(shape, TopAbs_EDGE, edge_map);
    model.edges.reserve(static_cast<size_t>(edge_map.Extent()));
    for (int i = 1; i <= edge_map.Extent(); ++i)
        model.edges.push_back(model_edge(TopoDS::Edge(edge_map(i))));

    // The same edges before conversion (same traversal of the same topology, same order).
    TopTools_IndexedMapOfShape original_edge_map;
    TopExp::MapShapes(original, TopAbs_EDGE, original_edge_map);

    // The faces before conversion, in the same explorer order, for Face::surface_kind.
    std::vector<TopoDS_Face> before;
    for (TopExp_Explorer it(original, TopAbs_FACE); it.More(); it.Next())
        before.push_back(TopoDS::Face(it.Current()));
    int occurrence = 0;
    std::vector<int> occurrence_to_face;
    for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next(), ++occurrence) {
        const TopoDS_Face& face = TopoDS::Face(it.Current());
        const size_t k = static_cast<size_t>(occurrence);
        TopoDS_Face was = k < before.size() ? before[k] : TopoDS_Face();
        std::string failure;
        try {
            geom::Face converted = convert_face(face, was, edge_map);
            double gap = loop_gap(converted);
            if (gap > kLoopGapRetry && !was.IsNull()) {
                geom::Face alone = convert_face_alone(was, original_edge_map);
                const double alone_gap = loop_gap(alone);
                if (alone_gap < gap) {
                    converted = std::move(alone);
                    gap = alone_gap;
                }
            }
            if (gap > kLoopGapMax)
                throw std::runtime_error("trim loops are not closed (relative gap " +
                                         geom::format_value(gap) + ")");
            if (!was.IsNull()) converted.color = styles.color(was, model);
            model.faces.push_back(std::move(converted));
            model.faces.back().source_entity = occurrence + 1;
            occurrence_to_face.push_back(static_cast<int>(model.faces.size()) - 1);
            continue;
        } catch (const Standard_Failure& e) {
            failure = failure_text(e);
        } catch (const std::exception& e) {
            failure = e.what();
        }
        occurrence_to_face.push_back(-1);
        model.warnings.push_back("face " + std::to_string(occurrence + 1) + " skipped: " + failure);
    }
    if (model.faces.empty())
        throw geom::ReadError(path, 0, occurrence == 0 ? "the STEP file has no faces"
                                                       : "no face of the STEP file converts");

    // Bodies: solids, then shells outside solids; faces outside shells are free. Faces are
    // matched to occurrences by (TShape, location, orientation), each used once.
    std::vector<bool> used(occurrence_to_face.size(), false);
    std::vector<TopoDS_Shape> occurrences;
    for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) occurrences.push_back(it.Current());
    size_t next = 0;  // explorers visit faces in the same order, so the search starts here
    auto faces_of = [&](const TopoDS_Shape& part) {
        std::vector<int> ids;
        for (TopExp_Explorer it(part, TopAbs_FACE); it.More(); it.Next())
            for (size_t step = 0; step < occurrences.size(); ++step) {
                const size_t k = (next + step) % occurrences.size();
                if (!used[k] && occurrences[k].IsEqual(it.Current())) {
                    used[k] = true;
                    next = k + 1;
                    if (occurrence_to_face[k] >= 0) ids.push_back(occurrence_to_face[k]);
                    break;
                }
            }
        return ids;
    };
    // Bodies are named and coloured from the shapes before conversion, visited in the
    // same order; faces without a colour of their own take their body's.
    auto add_body = [&](const TopoDS_Shape& part, const TopoDS_Shape& was, const std::string& kind, bool closed) {
        geom::Body body;
        body.name = was.IsNull() ? std::string() : styles.name(was);
        if (body.name.empty()) body.name = kind + " " + std::to_string(model.bodies.size() + 1);
        body.closed = closed;
        body.faces = faces_of(part);
        const int color = was.IsNull() ? -1 : styles.color(was, model);
        for (int f : body.faces)
            if (model.faces[f].color < 0) model.faces[f].color = color;
        if (!body.faces.empty()) model.bodies.push_back(std::move(body));
    };
    TopExp_Explorer was_solid(original, TopAbs_SOLID);
    for (TopExp_Explorer it(shape, TopAbs_SOLID); it.More(); it.Next()) {
        const TopoDS_Shape was = was_solid.More() ? was_solid.Current() : TopoDS_Shape();
        if (was_solid.More()) was_solid.Next();
        add_body(it.Current(), was, "solid", true);
    }
    TopExp_Explorer was_shell(original, TopAbs_SHELL, TopAbs_SOLID);
    for (TopExp_Explorer it(shape, TopAbs_SHELL, TopAbs_SOLID); it.More(); it.Next()) {
        const TopoDS_Shape was = was_shell.More() ? was_shell.Current() : TopoDS_Shape();
        if (was_shell.More()) was_shell.Next();
        add_body(it.Current(), was, "shell", BRep_Tool::IsClosed(it.Current()));
    }
    for (size_t k = 0; k < occurrences.size(); ++k)
        if (!used[k] && occurrence_to_face[k] >= 0) model.free_faces.push_back(occurrence_to_face[k]);
    return model;
}

}  // namespace trimkit::io
