#include "io/read_step_native.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <unordered_map>

#include "geom/error.h"
#include "io/face_loops.h"
#include "io/step_assembly.h"
#include "io/step_geometry.h"
#include "io/step_part21.h"
#include "io/step_styles.h"
#include "io/step_units.h"
#include "io/trim_loop_repair.h"

namespace trimkit::io {
namespace {

using Eigen::Vector3d;

// Points sampled along each edge for the face's boundary hint (sizes unbounded
// surfaces, step_geometry.h).
constexpr int kEdgeSamples = 16;
// Relative distance below which an edge's two vertex points are one (a closed edge).
constexpr double kSameVertex = 1e-9;

// A face with no FACE_OUTER_BOUND whose loops are all holes on a surface without
// boundary (holes_of_whole_surface) is the whole surface less the holes where OCCT's
// reader makes it so (ShapeFix_Face adds the natural bound): when the face marks its
// poles with VERTEX_LOOPs (Parasolid's balls), or on a sphere or torus with more than
// one hole. A single loop on a sphere or torus stays the region it encloses
// (bug28414_bug_toroidal_surface.stp), as OCCT takes it.
bool whole_surface_less_holes(const StepGeometry::Surface& S, const geom::Face& face, int pole_bounds) {
    const bool sphere_or_torus = S.kind == "sphere" || S.kind == "torus";
    if (pole_bounds == 0 && !(sphere_or_torus && face.loops.size() > 1)) return false;
    return holes_of_whole_surface(S.nurbs, face);
}

class Topology {
public:
    Topology(const StepPart21& file, const StepGeometry& geometry, geom::Model& model, ReadMonitor& monitor)
        : file_(file), geometry_(geometry), model_(model), monitor_(monitor) {}

    // The faces of a MANIFOLD_SOLID_BREP, BREP_WITH_VOIDS or SHELL_BASED_SURFACE_MODEL
    // as bodies.
    void add_solid(const StepInstance& solid, const std::string& type);

    // Model::faces index of each ADVANCED_FACE read, by its instance name.
    const std::unordered_map<long long, int>& faces() const { return face_index_; }
    // Bodies made from each solid or shell instance.
    const std::multimap<long long, int>& bodies() const { return body_index_; }

private:
    [[noreturn]] void fail(const StepInstance& at, const std::string& reason) const {
        throw geom::ReadError(file_.name(), at.line, "#" + std::to_string(at.id) + " " + reason);
    }
    const StepInstance& instance(const StepInstance& from, const StepValue& v, const char* what) const;
    const StepRecord& record(const StepInstance& inst, const char* type) const;
    const StepValue& param(const StepInstance& inst, const StepRecord& r, std::size_t i, const char* what) const;
    bool flag(const StepInstance& inst, const StepRecord& r, std::size_t i, const char* what) const;

    void add_shell(const StepInstance& shell, const std::string& name, long long owner);
    int add_face(const StepInstance& face);
    std::vector<BoundarySegment> loop_segments(const StepInstance& bound, long long surface, BoundaryHint& hint);
    void add_pcurve(bool oriented_forward, bool forward, long long surface, BoundarySegment& s) const;
    int edge(const StepInstance& edge_curve);

    // What an edge's PCURVEs need: its EDGE_CURVE's edge_geometry and the range of
    // that curve's parameter the edge uses (StepGeometry::EdgeRange), by Model::edges index.
    struct EdgeSource {
        long long curve = 0;
        StepGeometry::EdgeRange range;
    };

    const StepPart21& file_;
    const StepGeometry& geometry_;
    geom::Model& model_;
    ReadMonitor& monitor_;
    std::unordered_map<long long, int> edge_index_;
    std::vector<EdgeSource> edge_sources_;
    std::unordered_map<long long, int> face_index_;
    std::multimap<long long, int> body_index_;
    int face_number_ = 0;
};

const StepInstance& Topology::instance(const StepInstance& from, const StepValue& v, const char* what) const {
    if (v.kind != StepValue::Kind::kReference) fail(from, std::string(what) + " is not a reference");
    const StepInstance* target = file_.find(v.integer);
    if (!target) fail(from, std::string(what) + " #" + std::to_string(v.integer) + " is not defined");
    return *target;
}

const StepRecord& Topology::record(const StepInstance& inst, const char* type) const {
    const StepRecord* r = inst.record(type);
    if (!r) fail(inst, std::string("is not a ") + type);
    return *r;
}

const StepValue& Topology::param(const StepInstance& inst, const StepRecord& r, std::size_t i,
                                 const char* what) const {
    if (i >= r.params.size()) fail(inst, r.type + " has no " + what);
    return r.params[i];
}

bool Topology::flag(const StepInstance& inst, const StepRecord& r, std::size_t i, const char* what) const {
    const StepValue& v = param(inst, r, i, what);
    if (v.kind != StepValue::Kind::kEnum || (v.text != "T" && v.text != "F"))
        fail(inst, std::string(what) + " is not .T. or .F.");
    return v.text == "T";
}

void Topology::add_solid(const StepInstance& solid, const std::string& type) {
    const StepRecord& r = record(solid, type.c_str());
    const StepValue& name = param(solid, r, 0, "name");
    const std::string body_name = name.kind == StepValue::Kind::kString ? name.text : std::string();
    if (type == "SHELL_BASED_SURFACE_MODEL") {
        const StepValue& shells = param(solid, r, 1, "shells");
        if (shells.kind != StepValue::Kind::kList) fail(solid, "shells are not a list");
        for (const StepValue& s : shells.items) add_shell(instance(solid, s, "shell"), body_name, solid.id);
        return;
    }
    add_shell(instance(solid, param(solid, r, 1, "outer shell"), "outer shell"), body_name, solid.id);
    if (type != "BREP_WITH_VOIDS") return;
    const StepValue& voids = param(solid, r, 2, "voids");
    if (voids.kind != StepValue::Kind::kList) fail(solid, "voids are not a list");
    // A void's faces belong to the solid: one closed body with the outer shell's.
    const int body = static_cast<int>(model_.bodies.size()) - 1;
    for (const StepValue& v : voids.items) {
        const StepInstance& oriented = instance(solid, v, "void");
        const StepRecord& o = record(oriented, "ORIENTED_CLOSED_SHELL");
        const StepInstance& shell = instance(oriented, param(oriented, o, 2, "closed shell"), "closed shell");
        const StepRecord& cs = record(shell, "CLOSED_SHELL");
        const StepValue& faces = param(shell, cs, 1, "faces");
        if (faces.kind != StepValue::Kind::kList) fail(shell, "faces are not a list");
        for (const StepValue& f : faces.items) {
            const int index = add_face(instance(shell, f, "face"));
            if (index >= 0) model_.bodies[body].faces.push_back(index);
        }
    }
}

void Topology::add_shell(const StepInstance& shell, const std::string& name, long long owner) {
    const bool closed = shell.record("CLOSED_SHELL") != nullptr;
    const StepRecord* r = closed ? shell.record("CLOSED_SHELL") : shell.record("OPEN_SHELL");
    if (!r) unsupported_step_entity(file_, shell, "a shell of this kind");
    const StepValue& faces = param(shell, *r, 1, "faces");
    if (faces.kind != StepValue::Kind::kList) fail(shell, "faces are not a list");
    geom::Body body;
    body.name = name;
    body.closed = closed;
    for (const StepValue& f : faces.items) {
        const int index = add_face(instance(shell, f, "face"));
        if (index >= 0) body.faces.push_back(index);
    }
    body_index_.emplace(owner, static_cast<int>(model_.bodies.size()));
    body_index_.emplace(shell.id, static_cast<int>(model_.bodies.size()));
    model_.bodies.push_back(std::move(body));
}

// The face's index in Model::faces, or -1 when it is skipped (with a warning).
int Topology::add_face(const StepInstance& step_face) {
    monitor_.check();
    ++face_number_;
    if (const auto found = face_index_.find(step_face.id); found != face_index_.end()) return found->second;
    const StepRecord* r = step_face.record("ADVANCED_FACE");
    if (!r) r = step_face.record("FACE_SURFACE");
    if (!r) unsupported_step_entity(file_, step_face, "a face of this kind");
    try {
        const StepValue& name = param(step_face, *r, 0, "name");
        const StepValue& bounds = param(step_face, *r, 1, "bounds");
        if (bounds.kind != StepValue::Kind::kList) fail(step_face, "bounds are not a list");
        const StepValue& surface_ref = param(step_face, *r, 2, "face geometry");
        if (surface_ref.kind != StepValue::Kind::kReference) fail(step_face, "face geometry is not a reference");
        std::vector<std::vector<BoundarySegment>> loops;
        BoundaryHint hint;
        bool first_is_outer = false;
        int pole_bounds = 0;
        for (const StepValue& b : bounds.items) {
            const StepInstance& bound = instance(step_face, b, "bound");
            const bool outer = bound.record("FACE_OUTER_BOUND") != nullptr;
            std::vector<BoundarySegment> segments = loop_segments(bound, surface_ref.integer, hint);
            if (segments.empty()) {  // a VERTEX_LOOP: a pole, which the loops need not name
                ++pole_bounds;
                continue;
            }
            if (outer && !first_is_outer) {
                loops.insert(loops.begin(), std::move(segments));
                first_is_outer = true;
            } else {
                loops.push_back(std::move(segments));
            }
        }
        const StepGeometry::Surface S = geometry_.surface(surface_ref.integer, hint);
        geom::Face face;
        face.surface_kind = S.kind;
        face.reversed = !flag(step_face, *r, 3, "same sense") != S.map.flips_normal();
        face.name = name.kind == StepValue::Kind::kString ? name.text : std::string();
        face.source_entity = static_cast<int>(std::min<long long>(step_face.id, std::numeric_limits<int>::max()));
        FaceLoopsContext context;
        context.closure_tolerance = closure_tolerance(S.nurbs, 0.0);
        context.map_to_nurbs = [this, &S](const geom::NurbsCurve2d& c) { return geometry_.map_pcurve(S, c); };
        build_face_loops(S.nurbs, context, hint, loops, false, first_is_outer, face);
        const bool natural_outer = !first_is_outer && whole_surface_less_holes(S, face, pole_bounds);
        if (natural_outer) {
            build_face_loops(S.nurbs, context, hint, loops, true, false, face);
            face.warnings.push_back("no outer bound and every bound a hole on a closed surface: the face is the "
                                    "whole surface less the holes");
        } else if (first_is_outer) {
            settle_outer_loop(face, "bound");
        } else if (!face.loops.empty()) {
            // No FACE_OUTER_BOUND (allowed by Part 42): the loop of largest extent is outer.
            face.loops[enclosing_loop(face.loops, 0)].outer = true;
        }
        close_face_loops(face);
        model_.faces.push_back(std::move(face));
        face_index_[step_face.id] = static_cast<int>(model_.faces.size()) - 1;
        return face_index_[step_face.id];
    } catch (const geom::ReadError& e) {
        geom::skip_face(model_, "face " + std::to_string(face_number_) + " skipped: " + e.reason() + " (line " +
                              std::to_string(e.line()) + ")");
    } catch (const geom::InvalidInput& e) {
        geom::skip_face(model_, "face " + std::to_string(face_number_) + " skipped: #" + std::to_string(step_face.id) +
                              ": " + e.what());
    }
    return -1;
}

// The segments of one FACE_BOUND / FACE_OUTER_BOUND of a face on the surface
// instance `surface`, in the order the face runs them, each with its edge's 3D curve
// and, where the file gives one on that surface, its PCURVE (face_loops checks the
// PCURVE against the 3D curve and projects that instead when they disagree); their
// sample points added to `hint`.
std::vector<BoundarySegment> Topology::loop_segments(const StepInstance& bound, long long surface,
                                                     BoundaryHint& hint) {
    const StepRecord* r = bound.record("FACE_OUTER_BOUND");
    if (!r) r = &record(bound, "FACE_BOUND");
    const StepInstance& loop = instance(bound, param(bound, *r, 1, "loop"), "loop");
    const bool bound_forward = flag(bound, *r, 2, "orientation");
    if (loop.record("VERTEX_LOOP")) return {};
    const StepRecord* edge_loop = loop.record("EDGE_LOOP");
    if (!edge_loop) unsupported_step_entity(file_, loop, "a loop of this kind");
    const StepValue& edges = param(loop, *edge_loop, 1, "edge list");
    if (edges.kind != StepValue::Kind::kList) fail(loop, "edge list is not a list");
    std::vector<BoundarySegment> segments;
    for (const StepValue& e : edges.items) {
        const StepInstance& oriented = instance(loop, e, "oriented edge");
        const StepRecord& o = record(oriented, "ORIENTED_EDGE");
        const StepInstance& edge_curve = instance(oriented, param(oriented, o, 3, "edge element"), "edge element");
        const bool oriented_forward = flag(oriented, o, 4, "orientation");
        const bool forward = oriented_forward == bound_forward;
        BoundarySegment s;
        s.edge = edge(edge_curve);
        s.edge_reversed = !forward;
        const geom::NurbsCurve3d& c = *model_.edges[s.edge].curve;
        s.model = {forward ? c : c.reversed()};
        add_pcurve(oriented_forward, forward, surface, s);
        const auto [t0, t1] = c.domain();
        for (int k = 0; k <= kEdgeSamples; ++k) hint.push_back(c.evaluate(t0 + (t1 - t0) * k / kEdgeSamples));
        segments.push_back(std::move(s));
    }
    if (!bound_forward) std::reverse(segments.begin(), segments.end());
    return segments;
}

// s.param: the PCURVE of s.edge on the surface instance `surface` (of a SEAM_CURVE's
// two, the first for an ORIENTED_EDGE along the edge, else the second; face_loops
// shifts a loop's curves by whole periods to continue each other), oriented as
// s.model; none when the file has none there or it cannot be read.
void Topology::add_pcurve(bool oriented_forward, bool forward, long long surface, BoundarySegment& s) const {
    const EdgeSource& source = edge_sources_[static_cast<std::size_t>(s.edge)];
    std::optional<geom::NurbsCurve2d> pc =
        geometry_.edge_pcurve(source.curve, surface, source.range, oriented_forward);
    if (pc) s.param = {forward ? std::move(*pc) : pc->reversed()};
}

// The Model::edges index of an EDGE_CURVE, its curve running from its start vertex
// to its end vertex (translated once, shared by the faces that use it).
int Topology::edge(const StepInstance& edge_curve) {
    if (const auto found = edge_index_.find(edge_curve.id); found != edge_index_.end()) return found->second;
    const StepRecord& r = record(edge_curve, "EDGE_CURVE");
    auto vertex = [&](std::size_t i, const char* what) {
        const StepInstance& v = instance(edge_curve, param(edge_curve, r, i, what), what);
        const StepRecord& vp = record(v, "VERTEX_POINT");
        const StepValue& point = param(v, vp, 1, "vertex geometry");
        if (point.kind != StepValue::Kind::kReference) fail(v, "vertex geometry is not a reference");
        return geometry_.point(point.integer);
    };
    const Vector3d start = vertex(1, "edge start"), end = vertex(2, "edge end");
    const StepValue& curve = param(edge_curve, r, 3, "edge geometry");
    if (curve.kind != StepValue::Kind::kReference) fail(edge_curve, "edge geometry is not a reference");
    const double tol = kSameVertex * (1.0 + start.norm() + end.norm());
    geom::Edge e;
    EdgeSource source;
    source.curve = curve.integer;
    e.curve = geometry_.edge_curve(curve.integer, start, end, flag(edge_curve, r, 4, "same sense"), tol,
                                   &source.range);
    e.start = start;
    e.end = end;
    model_.edges.push_back(std::move(e));
    edge_sources_.push_back(source);
    return edge_index_[edge_curve.id] = static_cast<int>(model_.edges.size()) - 1;
}

// Lengths of the whole model in millimetres (read_step's unit).
void scale_to_millimetres(geom::Model& model, double metres_per_length) {
    const double factor = metres_per_length / 1e-3;
    model.units = "mm";
    model.scale_to_metres = 1e-3;
    if (std::abs(factor - 1.0) <= 1e-15) return;
    const Eigen::Affine3d S(Eigen::Scaling(factor));
    for (geom::Face& f : model.faces) f.surface = f.surface.transformed(S);
    for (geom::Edge& e : model.edges) {
        if (e.curve) e.curve = e.curve->transformed(S);
        if (e.start) e.start = factor * *e.start;
        if (e.end) e.end = factor * *e.end;
    }
    // A placement's rotation keeps; its translation is a length.
    for (geom::Instance& i : model.instances) i.transform.translation() *= factor;
}

// The name of the only PRODUCT, or "" when there are several or none.
std::string product_name(const StepPart21& file) {
    const std::vector<const StepInstance*> products = file.of_type("PRODUCT");
    if (products.size() != 1) return {};
    const StepRecord* r = products.front()->record("PRODUCT");
    for (std::size_t i : {1, 0})
        if (i < r->params.size() && r->params[i].kind == StepValue::Kind::kString && !r->params[i].text.empty())
            return r->params[i].text;
    return {};
}

}  // namespace

geom::Model read_step_native(const std::string& text, const std::string& name, ReadMonitor& monitor) {
    monitor.stage(0.0, 0.2);
    const StepPart21 file = StepPart21::parse(text, name);
    monitor.report(1.0);
    monitor.check();
    const StepUnits units = step_units(file);
    const StepGeometry geometry(file, units.radians_per_angle);
    // Assemblies (step_assembly.h): every solid is placed by the product structure.
    const bool assembly = step_has_assembly(file);
    const std::vector<StepOccurrence> occurrences = assembly ? step_occurrences(file, geometry)
                                                             : std::vector<StepOccurrence>();
    geom::Model model;
    Topology topology(file, geometry, model, monitor);
    monitor.stage(0.2, 1.0);
    const char* const solid_types[] = {"MANIFOLD_SOLID_BREP", "BREP_WITH_VOIDS", "SHELL_BASED_SURFACE_MODEL"};
    std::vector<std::pair<const StepInstance*, const char*>> solids;
    for (const char* type : solid_types)
        for (const StepInstance* s : file.of_type(type)) solids.emplace_back(s, type);
    if (solids.empty())
        throw UnsupportedStepEntity(name + ": no MANIFOLD_SOLID_BREP, BREP_WITH_VOIDS or SHELL_BASED_SURFACE_MODEL");
    std::sort(solids.begin(), solids.end(), [](const auto& a, const auto& b) { return a.first->id < b.first->id; });
    for (std::size_t i = 0; i < solids.size(); ++i) {
        // A BREP_WITH_VOIDS is also a MANIFOLD_SOLID_BREP (its supertype) in complex form.
        if (i > 0 && solids[i].first == solids[i - 1].first) continue;
        const bool voids = solids[i].first->record("BREP_WITH_VOIDS") != nullptr;
        topology.add_solid(*solids[i].first, voids ? "BREP_WITH_VOIDS" : solids[i].second);
        monitor.report(static_cast<double>(i + 1) / solids.size());
    }
    if (model.faces.empty()) throw geom::ReadError(name, 0, "no face of the STEP file could be read");
    if (assembly) place_step_occurrences(occurrences, topology.bodies(), model, name);
    const std::string product = product_name(file);
    for (geom::Body& b : model.bodies)
        if (b.name.empty() || b.name == "NONE") b.name = product;
    apply_step_colors(file, topology.faces(), topology.bodies(), model);
    scale_to_millimetres(model, units.metres_per_length);
    return model;
}

}  // namespace trimkit::io
