#include "io/occt_shape.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include <BRepBuilderAPI_NurbsConvert.hxx>
#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box2d.hxx>
#include <BndLib_Add2dCurve.hxx>
#include <Precision.hxx>
#include <ShapeExtend_Status.hxx>
#include <Standard_ErrorHandler.hxx>
#include <ShapeFix_Face.hxx>
#include <ShapeFix_Wire.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopLoc_Location.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include "geom/curve_box.h"
#include "geom/error.h"
#include "io/occt_geometry.h"
#include "io/occt_sewing.h"
#include "io/occt_support.h"

namespace trimkit::io {
namespace {

// P-curves mapped through a non-affine ParameterMap are refitted within this share
// of the surface's (u,v) domain (3D error about this share of the face's size,
// far below any tolerance a user meshes at).
constexpr double kPcurveRefitShare = 1e-7;
// Relative loop gaps (largest gap between consecutive coedges over the domain's
// size): above kLoopGapRetry the face is healed by ShapeFix_Face and translated
// again (the better result is kept); above kLoopGapMax it is skipped.
constexpr double kLoopGapRetry = 1e-6;
constexpr double kLoopGapMax = 1e-4;
// A joint closed in 3D counts as closed only while its (u,v) gap is below this share
// of the domain: the loop is bridged by a straight (u,v) segment, which across a
// period jump (0 to 2 pi on a closed surface, 3D gap 0) would cut the face in two.
constexpr double kUvGapClosedIn3d = 1e-2;
// trim_range's boxes are tight to this share of each curve's size.
constexpr double kTrimRangeTolerance = 1e-10;

// A coedge as OCCT gives it: its edge (oriented as the wire runs it) and its p-curve,
// translated in OCCT's parameters.
struct OcctCoedge {
    TopoDS_Edge edge;
    Handle(Geom2d_Curve) curve;
    double first = 0.0, last = 0.0;
    geom::NurbsCurve2d pcurve;
};

struct OcctWire {
    bool outer = false;
    std::vector<OcctCoedge> coedges;
};

// The (u, v) box of the p-curves in OCCT's parameters, tight: geom::curve_box of the
// translated curves (OCCT's AddOptimal, a particle-swarm search per B-spline curve,
// took 40 % of a .brep file's reading; AddOptimal is kept for a curve curve_box
// refuses); the surface's bounds when there is none.
Eigen::AlignedBox2d trim_range(const TopoDS_Face& face, const std::vector<OcctWire>& wires) {
    Bnd_Box2d box;
    for (const OcctWire& wire : wires)
        for (const OcctCoedge& c : wire.coedges) {
            try {
                const geom::NurbsCurve2d::Box hull = c.pcurve.control_box();
                const Eigen::AlignedBox2d tight = geom::curve_box(c.pcurve, kTrimRangeTolerance * hull.diagonal().norm());
                box.Update(tight.min().x(), tight.min().y(), tight.max().x(), tight.max().y());
            } catch (const geom::InvalidInput&) {
                BndLib_Add2dCurve::AddOptimal(c.curve, c.first, c.last, 0.0, box);
            }
        }
    double u0 = 0, v0 = 0, u1 = 0, v1 = 0;
    if (box.IsVoid()) {
        BRep_Tool::Surface(face)->Bounds(u0, u1, v0, v1);
        if (Precision::IsInfinite(u0) || Precision::IsInfinite(u1) || Precision::IsInfinite(v0) ||
            Precision::IsInfinite(v1))
            throw std::runtime_error("an unbounded surface without trim curves");
    } else {
        box.Get(u0, v0, u1, v1);
    }
    return Eigen::AlignedBox2d(Eigen::Vector2d(u0, v0), Eigen::Vector2d(u1, v1));
}

// The model-space edge: its 3D curve (located) where it has one, and its end vertices.
geom::Edge model_edge(const TopoDS_Edge& located) {
    const TopoDS_Edge edge = TopoDS::Edge(located.Oriented(TopAbs_FORWARD));
    geom::Edge out;
    TopoDS_Vertex v0, v1;
    TopLoc_Location loc;
    double first = 0, last = 0;
    Handle(Geom_Curve) c;
    occt_guarded([&] {
        TopExp::Vertices(edge, v0, v1);
        if (!v0.IsNull()) out.start = to_eigen(BRep_Tool::Pnt(v0));
        if (!v1.IsNull()) out.end = to_eigen(BRep_Tool::Pnt(v1));
        if (!BRep_Tool::Degenerated(edge)) c = BRep_Tool::Curve(edge, loc, first, last);
    });
    if (c.IsNull()) return out;
    try {
        // A fault in the translation is a Standard_Failure from this scope: `out` stays.
        geom::NurbsCurve3d curve = occt_guarded([&] { return translate_curve(c, first, last); });
        if (!loc.IsIdentity()) curve = curve.transformed(to_eigen(loc.Transformation()));
        out.curve = std::move(curve);
    } catch (const Standard_Failure&) {
        // No usable 3D curve: the coedges still carry the p-curves.
    } catch (const std::exception&) {
    }
    return out;
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

// The wires of the (forward) face, the outer one first, their p-curves translated.
// Throws for an edge without a p-curve, UntranslatedKind for a curve kind without a
// translation.
std::vector<OcctWire> occt_wires(const TopoDS_Face& face) {
    std::vector<OcctWire> wires;
    const TopoDS_Wire outer = BRepTools::OuterWire(face);
    for (const TopoDS_Wire& wire : ordered_wires(face)) {
        OcctWire w;
        w.outer = !outer.IsNull() && wire.IsSame(outer);
        for (BRepTools_WireExplorer it(wire, face); it.More(); it.Next()) {
            OcctCoedge c;
            c.edge = it.Current();
            c.curve = BRep_Tool::CurveOnSurface(c.edge, face, c.first, c.last);
            if (c.curve.IsNull()) throw std::runtime_error("an edge has no curve on the face");
            c.pcurve = translate_curve(c.curve, c.first, c.last);
            w.coedges.push_back(std::move(c));
        }
        wires.push_back(std::move(w));
    }
    return wires;
}

// One face occurrence to a geom::Face; coedges name their edges by `edges` (index
// + offset into Model::edges; -1 for an edge not in the map). Throws on failure.
geom::Face convert_face(const TopoDS_Face& located, const TopTools_IndexedMapOfShape& edges, int edge_offset) {
    geom::Face out;
    out.reversed = located.Orientation() == TopAbs_REVERSED;
    // Loops are read from the forward face, so the outer loop runs counter-clockwise;
    // translated_face mirrors them for a reversed face (face.h's convention).
    const TopoDS_Face face = TopoDS::Face(located.Oriented(TopAbs_FORWARD));
    TopLoc_Location loc;
    const Handle(Geom_Surface) s = BRep_Tool::Surface(face, loc);
    if (s.IsNull()) throw std::runtime_error("the face has no surface");
    // The p-curves translated once: for the surface's range, then mapped into its (u,v).
    const std::vector<OcctWire> wires = occt_wires(face);
    TranslatedSurface translated = translate_surface(s, trim_range(face, wires));
    out.surface = loc.IsIdentity() ? std::move(translated.nurbs)
                                   : translated.nurbs.transformed(to_eigen(loc.Transformation()));
    out.surface_kind = translated.kind;
    if (translated.map.flips_normal()) out.reversed = !out.reversed;
    const auto [u0, u1] = out.surface.domain_u();
    const auto [v0, v1] = out.surface.domain_v();
    const double refit_tol = kPcurveRefitShare * std::max(u1 - u0, v1 - v0);

    for (const OcctWire& wire : wires) {
        geom::Loop loop;
        loop.outer = wire.outer;
        for (const OcctCoedge& c : wire.coedges) {
            geom::NurbsCurve2d pcurve = translated.map.map_curve(c.pcurve, refit_tol);
            geom::Coedge coedge;
            coedge.curve = c.edge.Orientation() == TopAbs_REVERSED ? pcurve.reversed() : std::move(pcurve);
            const int index = edges.FindIndex(c.edge);
            coedge.edge = index > 0 ? index - 1 + edge_offset : -1;
            coedge.edge_reversed = c.edge.Orientation() == TopAbs_REVERSED;
            loop.coedges.push_back(std::move(coedge));
        }
        if (!loop.coedges.empty()) out.loops.push_back(std::move(loop));
    }
    if (out.loops.empty()) out.loops.push_back(geom::natural_boundary_loop(out.surface));
    return out;
}

// The largest gap between the end of a coedge and the start of the next. A joint's
// gap is the smaller of its (u,v) gap relative to the domain's size and its 3D gap
// relative to the face's size (the box of its coedges' ends and middles): a joint closed in 3D
// may be open in (u,v) where the surface hardly moves along u (Bottom.brep's blend
// corner: 0.0177 in u, 0.001 in 3D on a face 19 across; up to kUvGapClosedIn3d), and
// one closed in (u,v) may be open in 3D by the file's edge tolerance. A joint whose
// ends lie within `closed_within` in 3D is closed (vertex_reach).
double loop_gap(const geom::Face& face, double closed_within = 0.0) {
    const auto [u0, u1] = face.surface.domain_u();
    const auto [v0, v1] = face.surface.domain_v();
    const auto at = [&](const geom::NurbsCurve2d& c, double t) {
        const Eigen::Vector2d uv = c.evaluate(t);
        return std::pair{uv, face.surface.evaluate(uv.x(), uv.y())};
    };
    Eigen::AlignedBox3d box;
    std::vector<std::pair<double, double>> joints;  // (u,v) gap, 3D gap
    for (const auto& loop : face.loops)
        for (size_t k = 0; k < loop.coedges.size(); ++k) {
            const auto& a = loop.coedges[k].curve;
            const auto& b = loop.coedges[(k + 1) % loop.coedges.size()].curve;
            const auto [uv_end, xyz_end] = at(a, a.domain().second);
            const auto [uv_start, xyz_start] = at(b, b.domain().first);
            box.extend(xyz_end);
            box.extend(at(a, 0.5 * (a.domain().first + a.domain().second)).second);
            joints.emplace_back((uv_end - uv_start).norm(), (xyz_end - xyz_start).norm());
        }
    const double domain = std::max(u1 - u0, v1 - v0), size = box.isEmpty() ? 0.0 : box.diagonal().norm();
    double gap = 0;
    for (const auto& [uv, xyz] : joints) {
        if (xyz <= closed_within) continue;
        const double in_uv = uv / domain, in_3d = size > 0 && in_uv <= kUvGapClosedIn3d ? xyz / size : in_uv;
        gap = std::max(gap, std::min(in_uv, in_3d));
    }
    return gap;
}

// How far apart in 3D the ends of two p-curves meeting at a vertex of `face` may be
// while both lie within the vertex's tolerance (OCCT takes such a joint as closed;
// ul_to252.step's lead profiles, written to 3 decimals, miss by 5.7e-4 under
// tolerances of 3.9e-4): twice the face's largest vertex tolerance.
double vertex_reach(const TopoDS_Face& face) {
    double largest = 0.0;
    for (TopExp_Explorer it(face, TopAbs_VERTEX); it.More(); it.Next())
        largest = std::max(largest, BRep_Tool::Tolerance(TopoDS::Vertex(it.Current())));
    return 2.0 * largest;
}

// The face healed by ShapeFix_Face (wire order, connection, small edges, missing and
// gapped p-curves, degenerated edges, wire orientation), and what it did.
TopoDS_Face healed_face(const TopoDS_Face& face, std::string& done) {
    const Handle(ShapeFix_Face) fix = occt_guarded([&] { return Handle(ShapeFix_Face)(new ShapeFix_Face(face)); });
    // P-curves whose ends miss their vertices are dropped and projected again from
    // the 3D curves; the remaining gaps are closed in 2D and 3D.
    fix->FixWireTool()->FixRemovePCurveMode() = 1;
    fix->FixWireTool()->FixAddPCurveMode() = 1;
    fix->FixWireTool()->FixGaps2dMode() = 1;
    fix->FixWireTool()->FixGaps3dMode() = 1;
    occt_guarded([&] { fix->Perform(); });
    const Handle(ShapeFix_Wire) wire = fix->FixWireTool();
    std::vector<std::string> what;
    if (wire->StatusReorder(ShapeExtend_DONE)) what.push_back("wire order");
    if (wire->StatusConnected(ShapeExtend_DONE)) what.push_back("edge ends connected");
    if (wire->StatusSmall(ShapeExtend_DONE)) what.push_back("small edges removed");
    if (wire->StatusEdgeCurves(ShapeExtend_DONE)) what.push_back("p-curves rebuilt");
    if (wire->StatusGaps2d(ShapeExtend_DONE)) what.push_back("2D gaps closed");
    if (wire->StatusGaps3d(ShapeExtend_DONE)) what.push_back("3D gaps closed");
    if (wire->StatusDegenerated(ShapeExtend_DONE)) what.push_back("degenerated edges");
    if (wire->StatusLacking(ShapeExtend_DONE)) what.push_back("lacking edges added");
    if (what.empty() && fix->Status(ShapeExtend_DONE1)) what.push_back("wires fixed");
    if (fix->Status(ShapeExtend_DONE2)) what.push_back("wire orientation");
    if (fix->Status(ShapeExtend_DONE3)) what.push_back("seam added");
    if (fix->Status(ShapeExtend_DONE5)) what.push_back("natural bounds added");
    for (const std::string& w : what) done += (done.empty() ? "" : ", ") + w;
    if (done.empty()) done = "no change";
    TopoDS_Face out = fix->Face();
    out.Orientation(face.Orientation());
    return out;
}

// The edge indices of a face's coedges, loop by loop, in convert_face's order.
std::vector<std::vector<int>> coedge_edges(const TopoDS_Face& located, const TopTools_IndexedMapOfShape& edges,
                                           int edge_offset) {
    const TopoDS_Face face = TopoDS::Face(located.Oriented(TopAbs_FORWARD));
    std::vector<std::vector<int>> ids;
    for (const TopoDS_Wire& wire : ordered_wires(face)) {
        std::vector<int> loop;
        for (BRepTools_WireExplorer it(wire, face); it.More(); it.Next()) {
            const int index = edges.FindIndex(it.Current());
            loop.push_back(index > 0 ? index - 1 + edge_offset : -1);
        }
        if (!loop.empty()) ids.push_back(std::move(loop));
    }
    return ids;
}

// A face whose surface kind has no direct translation, converted by OCCT's
// NurbsConvert on its own; coedges keep the original face's shared edges.
geom::Face converted_face(const TopoDS_Face& located, const TopTools_IndexedMapOfShape& edges, int edge_offset) {
    const TopoDS_Face alone =
        occt_guarded([&] { return TopoDS::Face(BRepBuilderAPI_NurbsConvert(located, true).Shape()); });
    geom::Face out = convert_face(alone, TopTools_IndexedMapOfShape(), 0);
    out.surface_kind = surface_kind_name(BRep_Tool::Surface(located));
    const auto ids = coedge_edges(located, edges, edge_offset);
    if (ids.size() != out.loops.size()) return out;  // natural boundary, or changed loops: not shared
    for (size_t l = 0; l < ids.size(); ++l) {
        if (ids[l].size() != out.loops[l].coedges.size()) continue;
        for (size_t k = 0; k < ids[l].size(); ++k) out.loops[l].coedges[k].edge = ids[l][k];
    }
    return out;
}

// Each loop traversed the other way: coedges in reverse order, each curve reversed
// and running the other way along its edge.
void mirror_loops(geom::Face& face) {
    for (geom::Loop& loop : face.loops) {
        std::reverse(loop.coedges.begin(), loop.coedges.end());
        for (geom::Coedge& coedge : loop.coedges) {
            coedge.curve = coedge.curve.reversed();
            coedge.edge_reversed = !coedge.edge_reversed;
        }
    }
}

// The face translated; a reversed face's loops mirrored, so that the outer loop of
// a face whose normal is Su x Sv runs counter-clockwise and of a reversed one
// clockwise, as the IGES reader gives them (face.h).
geom::Face translated_face(const TopoDS_Face& face, const TopTools_IndexedMapOfShape& edges, int edge_offset) {
    geom::Face out;
    try {
        out = convert_face(face, edges, edge_offset);
    } catch (const UntranslatedKind&) {
        out = converted_face(face, edges, edge_offset);
    }
    if (face.Orientation() == TopAbs_REVERSED) mirror_loops(out);
    return out;
}

// The face translated, healed and translated again when its loops do not close. The
// translation, the healing and the second translation are each a signal-catching scope
// of their own (occt_guarded): after a memory fault in one of them, what this function
// holds (the first translation, the failure text) is still here and destroyed normally.
geom::Face checked_face(const TopoDS_Face& face, const TopTools_IndexedMapOfShape& edges, int edge_offset) {
    // A damaged .brep can leave a face without its surface: nothing to translate or heal
    // (ShapeFix_Face's constructor faults on it).
    if (occt_guarded([&] { return BRep_Tool::Surface(face).IsNull(); }))
        throw std::runtime_error("the face has no surface");
    std::string failure;
    std::optional<geom::Face> best;
    double gap = 0;
    try {
        best = occt_guarded([&] { return translated_face(face, edges, edge_offset); });
        gap = loop_gap(*best);
        if (gap <= kLoopGapRetry) return std::move(*best);
        failure = "trim loops are not closed (relative gap " + geom::format_value(gap) + ")";
    } catch (const Standard_Failure& e) {
        failure = failure_text(e);
    } catch (const std::exception& e) {
        failure = e.what();
    }
    std::string done;
    try {
        const TopoDS_Face healed_shape = healed_face(face, done);
        geom::Face healed = occt_guarded([&] { return translated_face(healed_shape, edges, edge_offset); });
        const double healed_gap = loop_gap(healed);
        if (!best || healed_gap < gap) {
            healed.warnings.push_back("healed by ShapeFix_Face (" + done + "): " + failure);
            best = std::move(healed);
            gap = healed_gap;
        }
    } catch (const Standard_Failure& e) {
        if (!best) throw std::runtime_error(failure + "; healing failed: " + failure_text(e));
    } catch (const std::exception& e) {
        if (!best) throw std::runtime_error(failure + "; healing failed: " + e.what());
    }
    if (gap > kLoopGapMax && loop_gap(*best, vertex_reach(face)) > kLoopGapMax)
        throw std::runtime_error("trim loops are not closed after healing (relative gap " +
                                 geom::format_value(gap) + ")");
    return std::move(*best);
}

}  // namespace

std::vector<int> add_shape(geom::Model& model, const TopoDS_Shape& part, const ShapeStyle& style,
                           const std::string& fallback_name, int& face_number, ReadMonitor* monitor) {
    const SewnShape sewn = sew_loose_faces(part);
    const TopoDS_Shape& shape = sewn.shape;
    if (sewn.sewn)
        model.warnings.push_back((fallback_name.empty() ? std::string("a part") : "part '" + fallback_name + "'") +
                                 ": its faces did not share their edges; sewn by BRepBuilderAPI_Sewing (free edges " +
                                 std::to_string(sewn.free_edges_before) + " -> " +
                                 std::to_string(sewn.free_edges_after) + ")");
    TopTools_IndexedMapOfShape edge_map;
    TopExp::MapShapes(shape, TopAbs_EDGE, edge_map);
    const int edge_offset = static_cast<int>(model.edges.size());
    for (int i = 1; i <= edge_map.Extent(); ++i) model.edges.push_back(model_edge(TopoDS::Edge(edge_map(i))));

    std::vector<TopoDS_Shape> occurrences;
    std::vector<int> occurrence_face;
    for (TopExp_Explorer it(shape, TopAbs_FACE); it.More(); it.Next()) {
        if (monitor) monitor->check();
        const TopoDS_Face& face = TopoDS::Face(it.Current());
        occurrences.push_back(face);
        ++face_number;
        try {
            // checked_face catches signals in its own scopes; the colour lookup (XCAF) in one here.
            geom::Face converted = checked_face(face, edge_map, edge_offset);
            converted.source_entity = face_number;
            if (style.color)
                converted.color = occt_guarded([&] { return style.color(original_face(sewn, face), model); });
            model.faces.push_back(std::move(converted));
            occurrence_face.push_back(static_cast<int>(model.faces.size()) - 1);
            continue;
        } catch (const Standard_Failure& e) {
            geom::skip_face(model, "face " + std::to_string(face_number) + " skipped: " + failure_text(e));
        } catch (const std::exception& e) {
            geom::skip_face(model, "face " + std::to_string(face_number) + " skipped: " + e.what());
        }
        occurrence_face.push_back(-1);
    }

    // Bodies: solids, then shells outside solids, then (if neither) all faces as one;
    // faces are matched to occurrences by (TShape, location, orientation), each once.
    std::vector<bool> used(occurrences.size(), false);
    size_t next = 0;  // explorers visit faces in the same order, so the search starts here
    auto faces_of = [&](const TopoDS_Shape& part) {
        std::vector<int> ids;
        for (TopExp_Explorer it(part, TopAbs_FACE); it.More(); it.Next())
            for (size_t step = 0; step < occurrences.size(); ++step) {
                const size_t k = (next + step) % occurrences.size();
                if (!used[k] && occurrences[k].IsEqual(it.Current())) {
                    used[k] = true;
                    next = k + 1;
                    if (occurrence_face[k] >= 0) ids.push_back(occurrence_face[k]);
                    break;
                }
            }
        return ids;
    };
    std::vector<int> bodies;
    auto add_body = [&](const TopoDS_Shape& part, const std::string& kind, bool closed) {
        geom::Body body;
        body.name = style.name ? occt_guarded([&] { return style.name(part); }) : std::string();
        if (body.name.empty()) body.name = fallback_name.empty() ? kind + " " + std::to_string(model.bodies.size() + 1)
                                                                 : fallback_name;
        body.closed = closed;
        body.faces = faces_of(part);
        const int color = style.color ? occt_guarded([&] { return style.color(part, model); }) : -1;
        for (int f : body.faces)
            if (model.faces[f].color < 0) model.faces[f].color = color;
        if (body.faces.empty()) return;
        model.bodies.push_back(std::move(body));
        bodies.push_back(static_cast<int>(model.bodies.size()) - 1);
    };
    for (TopExp_Explorer it(shape, TopAbs_SOLID); it.More(); it.Next()) add_body(it.Current(), "solid", true);
    for (TopExp_Explorer it(shape, TopAbs_SHELL, TopAbs_SOLID); it.More(); it.Next())
        add_body(it.Current(), "shell", BRep_Tool::IsClosed(it.Current()));
    // Faces in no shell: one body of their own (an assembly part must be placeable).
    geom::Body loose;
    for (size_t k = 0; k < occurrences.size(); ++k)
        if (!used[k] && occurrence_face[k] >= 0) loose.faces.push_back(occurrence_face[k]);
    if (!loose.faces.empty()) {
        loose.name = fallback_name.empty() ? "faces " + std::to_string(model.bodies.size() + 1) : fallback_name;
        model.bodies.push_back(std::move(loose));
        bodies.push_back(static_cast<int>(model.bodies.size()) - 1);
    }
    return bodies;
}

}  // namespace trimkit::io
