// Topology entities of IgesReader: 144 trimmed surface (with 142 curves on
// surface), 143 bounded surface (with 141 boundaries), bare surfaces (natural
// boundary), and the B-rep 186 manifold solid / 514 shell / 510 face / 508 loop /
// 504 edge list / 502 vertex list with shared edges. The entities become boundary
// segments; io/face_loops.h turns them into the face's trim loops.
#include <algorithm>
#include <cmath>

#include "geom/error.h"
#include "io/face_loops.h"
#include "io/iges_reader.h"
#include "io/trim_loop_repair.h"

namespace trimkit::io {

using Eigen::Vector3d;

FaceLoopsContext IgesReader::face_loops_context(const IgesSurface& s) const {
    FaceLoopsContext context;
    context.closure_tolerance = closure_tolerance(s.nurbs);
    context.resolution = file_.global().min_resolution;
    context.map_to_nurbs = [this, &s](const geom::NurbsCurve2d& c) { return map_to_nurbs(s, c); };
    return context;
}

// Finishes a face: closes and orients loops, applies the placement, stores it.
static int store_face(IgesReader& r, geom::Face face, const Eigen::Affine3d& T) {
    close_face_loops(face);
    if (!T.matrix().isIdentity(0)) face.surface = face.surface.transformed(T);
    r.seen_box_.extend(face.surface.control_box());
    r.model().faces.push_back(std::move(face));
    return static_cast<int>(r.model().faces.size()) - 1;
}

std::vector<int> IgesReader::read_face_entity(int de, const Eigen::Affine3d& placement) {
    Nesting guard(*this, de);
    const IgesDirectoryEntry& e = entry_of(de);
    geom::Face face;
    face.source_entity = de;
    const Eigen::Affine3d T = placement * transform_of(de);
    std::vector<int> props;
    int surface_de = 0;

    if (e.type == 144 || e.type == 143) {
        IgesParameterCursor c(file_, file_.index_of(de));
        std::vector<int> boundaries;
        bool first_is_outer = true;
        bool natural_outer = false;
        if (e.type == 144) {
            surface_de = c.pointer("surface");
            const int n1 = c.integer_or("outer boundary flag N1", 0);
            const int n2 = c.count("inner boundary count N2", 1);
            const int outer = c.pointer("outer boundary");
            for (int i = 0; i < n2; ++i) boundaries.push_back(c.pointer("inner boundary"));
            if (n1 == 0 || outer == 0) {
                natural_outer = true;
                first_is_outer = false;
            } else {
                boundaries.insert(boundaries.begin(), outer);
            }
        } else {
            c.integer_or("representation type", 0);
            surface_de = c.pointer("surface");
            const int n = c.count("boundary count", 1);
            for (int i = 0; i < n; ++i) boundaries.push_back(c.pointer("boundary"));
        }
        props = c.property_pointers();
        if (surface_de == 0) c.fail("no surface");
        // Read the boundaries' curves first: unbounded surfaces are sized from them.
        std::vector<std::vector<BoundarySegment>> loops;
        BoundaryHint hint;
        for (int b : boundaries) {
            std::vector<BoundarySegment> segs;
            if (b == 0) {
                loops.push_back(std::move(segs));
                continue;
            }
            const IgesDirectoryEntry& be = entry_of(b);
            IgesParameterCursor q(file_, file_.index_of(b));
            if (be.type == 142) {
                q.integer_or("creation flag", 0);
                q.pointer("surface");
                const int bp = q.pointer("parameter curve");
                const int cp = q.pointer("model curve");
                const int pref = q.integer_or("preference", 0);
                BoundarySegment s;
                if (cp != 0) {
                    try {
                        s.model = curve(cp);
                    } catch (const geom::ReadError& err) {
                        face.warnings.push_back("model curve D" + std::to_string(cp) + " skipped: " + err.reason());
                    }
                }
                if (bp != 0) {
                    try {
                        s.param = parameter_curve(bp);
                    } catch (const geom::ReadError& err) {
                        face.warnings.push_back("parameter curve D" + std::to_string(bp) + " skipped: " + err.reason());
                    }
                }
                s.prefer_model = pref == 2;
                s.prefer_param = pref == 1;
                add_points(&hint, s.model);
                segs.push_back(std::move(s));
            } else if (be.type == 141) {
                const int type = q.integer_or("type", 0);
                q.integer_or("preference", 0);
                q.pointer("surface");
                const int n = q.count("curve count", 3);
                for (int i = 0; i < n; ++i) {
                    BoundarySegment s;
                    const int cp = q.pointer("model curve");
                    const int sense = q.integer_or("sense", 1);
                    const int k = q.count("parameter curve count", 1);
                    std::vector<int> pcs;
                    for (int j = 0; j < k; ++j) pcs.push_back(q.pointer("parameter curve"));
                    if (cp != 0) {
                        try {
                            s.model = sense == 2 ? reversed_chain(curve(cp)) : curve(cp);
                        } catch (const geom::ReadError& err) {
                            face.warnings.push_back("model curve D" + std::to_string(cp) + " skipped: " + err.reason());
                        }
                    }
                    if (type == 1) s.param = parameter_curves(pcs, &face.warnings);
                    add_points(&hint, s.model);
                    segs.push_back(std::move(s));
                }
            } else {
                q.fail("boundary D" + std::to_string(b) + " is entity " + std::to_string(be.type) +
                       ", expected " + (e.type == 144 ? "142" : "141"));
            }
            loops.push_back(std::move(segs));
        }
        IgesSurface S = surface(surface_de, hint.empty() ? nullptr : &hint);
        face.surface_kind = S.kind;
        build_face_loops(S.nurbs, face_loops_context(S), hint, loops, natural_outer, first_is_outer, face);
        if (first_is_outer) settle_outer_loop(face, "boundary");
    } else if (is_surface_type(e.type)) {
        // A bare surface: its natural boundary.
        surface_de = de;
        IgesSurface S = surface(de, nullptr);
        face.surface = S.nurbs;
        face.surface_kind = S.kind;
        face.loops.push_back(geom::natural_boundary_loop(S.nurbs));
        // The surface's own transform is already in S; only the placement remains.
        face.color = color_of(de);
        face.name = name_of(de, {});
        return {store_face(*this, std::move(face), placement)};
    } else if (e.type == 510) {
        return {read_brep_face(de, placement, false)};
    } else {
        fail(de, "entity " + std::to_string(e.type) + " is not a face");
    }
    face.color = color_of(de);
    if (face.color < 0 && surface_de) face.color = color_of(surface_de);
    face.name = name_of(de, props);
    if (face.name.empty() && surface_de) face.name = name_of(surface_de, {});
    return {store_face(*this, std::move(face), T)};
}

int IgesReader::read_brep_face(int de, const Eigen::Affine3d& placement, bool reversed) {
    Nesting guard(*this, de);
    const IgesDirectoryEntry& e = entry_of(de);
    if (e.type != 510) fail(de, "shell member is entity " + std::to_string(e.type) + ", expected 510");
    IgesParameterCursor c(file_, file_.index_of(de));
    const int surface_de = c.pointer("surface");
    const int n = c.count("loop count", 1, 1);
    const int outer_flag = c.integer_or("outer loop flag", 1);
    std::vector<int> loop_des;
    for (int i = 0; i < n; ++i) loop_des.push_back(c.pointer("loop"));
    const std::vector<int> props = c.property_pointers();
    if (surface_de == 0) c.fail("no surface");

    geom::Face face;
    face.source_entity = de;
    face.reversed = reversed;
    std::vector<std::vector<BoundarySegment>> loops;
    BoundaryHint hint;
    for (int l : loop_des) {
        std::vector<BoundarySegment> segs;
        if (l == 0 || entry_of(l).type != 508) {
            face.warnings.push_back("loop D" + std::to_string(l) + " is not a 508 loop; skipped");
            loops.push_back(std::move(segs));
            continue;
        }
        IgesParameterCursor q(file_, file_.index_of(l));
        const int ne = q.count("edge count", 5);
        for (int i = 0; i < ne; ++i) {
            const int type = q.integer_or("edge type", 0);
            const int list = q.pointer("edge list");
            const int index = q.integer("edge index");
            const int of = q.integer_or("orientation flag", 1);
            const int k = q.count("parameter curve count", 2);
            std::vector<int> pcs;
            for (int j = 0; j < k; ++j) {
                q.integer_or("isoparametric flag", 0);
                pcs.push_back(q.pointer("parameter curve"));
            }
            if (type != 0 || list == 0) continue;  // a vertex: bridged by the loop closer
            BoundarySegment s;
            s.edge_reversed = of == 0;
            try {
                const auto [first, local] = brep_edge(list, index, placement);
                s.edge = first;
                s.model = s.edge_reversed ? reversed_chain(*local) : *local;
            } catch (const geom::ReadError& err) {
                face.warnings.push_back("edge " + std::to_string(index) + " of D" + std::to_string(list) +
                                        " skipped: " + err.reason());
            }
            s.param = parameter_curves(pcs, &face.warnings);
            add_points(&hint, s.model);
            segs.push_back(std::move(s));
        }
        loops.push_back(std::move(segs));
    }
    IgesSurface S = surface(surface_de, hint.empty() ? nullptr : &hint);
    face.surface_kind = S.kind;
    build_face_loops(S.nurbs, face_loops_context(S), hint, loops, false, outer_flag != 0, face);
    if (outer_flag != 0) {
        settle_outer_loop(face, "loop");
    } else if (!face.loops.empty()) {
        // Without the outer flag, the loop with the largest extent is the outer one.
        std::size_t outer_index = 0;
        for (std::size_t i = 1; i < face.loops.size(); ++i)
            if (std::fabs(signed_area(face.loops[i])) > std::fabs(signed_area(face.loops[outer_index])))
                outer_index = i;
        face.loops[outer_index].outer = true;
    }
    face.color = color_of(de);
    if (face.color < 0) face.color = color_of(surface_de);
    face.name = name_of(de, props);
    if (face.name.empty()) face.name = name_of(surface_de, {});
    return store_face(*this, std::move(face), placement * transform_of(de));
}

std::pair<int, const std::vector<geom::NurbsCurve3d>*> IgesReader::brep_edge(
    int list, int index, const Eigen::Affine3d& placement) {
    auto it = edge_index_.find({list, index});
    if (it != edge_index_.end()) return {it->second, &curve(edge_curve_.at({list, index}))};
    const IgesDirectoryEntry& le = entry_of(list);
    if (le.type != 504) fail(list, "edge list pointer refers to entity " + std::to_string(le.type));
    IgesParameterCursor c(file_, file_.index_of(list));
    const int n = c.count("edge count", 5);
    if (index < 1 || index > n)
        c.fail("edge index " + std::to_string(index) + " is outside 1.." + std::to_string(n));
    c.skip(static_cast<std::size_t>(index - 1) * 5);
    const int cu = c.pointer("edge curve");
    const int sv = c.pointer("start vertex list"), si = c.integer_or("start vertex index", 0);
    const int tv = c.pointer("end vertex list"), ti = c.integer_or("end vertex index", 0);
    if (cu == 0) c.fail("edge " + std::to_string(index) + " has no curve");
    const std::vector<geom::NurbsCurve3d>& local = curve(cu);
    const int first = static_cast<int>(model_.edges.size());
    const Eigen::Affine3d T = placement;
    for (const auto& k : local) {
        geom::Edge edge;
        edge.curve = T.matrix().isIdentity(0) ? k : k.transformed(T);
        model_.edges.push_back(std::move(edge));
    }
    auto vertex = [&](int vl, int vi) -> std::optional<Vector3d> {
        if (vl == 0 || entry_of(vl).type != 502) return std::nullopt;
        try {
            IgesParameterCursor v(file_, file_.index_of(vl));
            const int nv = v.count("vertex count", 3);
            if (vi < 1 || vi > nv) return std::nullopt;
            v.skip(static_cast<std::size_t>(vi - 1) * 3);
            return T * (transform_of(vl) * v.point("vertex"));
        } catch (const geom::ReadError&) {
            return std::nullopt;
        }
    };
    model_.edges[first].start = vertex(sv, si);
    model_.edges.back().end = vertex(tv, ti);
    edge_index_[{list, index}] = first;
    edge_curve_[{list, index}] = cu;
    return {first, &local};
}

int IgesReader::read_body(int de, const Eigen::Affine3d& placement) {
    Nesting guard(*this, de);
    const IgesDirectoryEntry& e = entry_of(de);
    IgesParameterCursor c(file_, file_.index_of(de));
    geom::Body body;
    // (shell, flipped) pairs.
    std::vector<std::pair<int, bool>> shells;
    if (e.type == 186) {
        const int shell = c.pointer("shell");
        const int sof = c.integer_or("shell orientation", 1);
        const int nv = c.count("void count", 2);
        shells.emplace_back(shell, sof == 0);
        for (int i = 0; i < nv; ++i) {
            const int v = c.pointer("void shell");
            const int vof = c.integer_or("void orientation", 1);
            shells.emplace_back(v, vof == 0);
        }
        body.closed = true;
    } else if (e.type == 514) {
        shells.emplace_back(de, false);
        body.closed = e.form != 2;
    } else {
        fail(de, "entity " + std::to_string(e.type) + " is not a body");
    }
    const std::vector<int> props = c.property_pointers();
    body.name = name_of(de, props);
    const Eigen::Affine3d T = placement * transform_of(de);
    edge_index_.clear();
    edge_curve_.clear();
    const int body_color = color_of(de);
    for (const auto& [shell, flipped] : shells) {
        if (shell == 0) continue;
        if (entry_of(shell).type != 514) {
            warn("D" + std::to_string(de) + ": shell D" + std::to_string(shell) + " is not a 514 shell; skipped");
            continue;
        }
        IgesParameterCursor s(file_, file_.index_of(shell));
        const int nf = s.count("face count", 2);
        std::vector<std::pair<int, int>> faces;
        for (int i = 0; i < nf; ++i) {
            const int f = s.pointer("face");
            const int of = s.integer_or("face orientation", 1);
            faces.emplace_back(f, of);
        }
        const Eigen::Affine3d Ts = shell == de ? T : T * transform_of(shell);
        for (const auto& [f, of] : faces) {
            if (f == 0) continue;
            try {
                const int index = read_brep_face(f, Ts, (of == 0) != flipped);
                if (model_.faces[index].color < 0) model_.faces[index].color = body_color;
                body.faces.push_back(index);
            } catch (const geom::ReadError& err) {
                geom::skip_face(model_, "D" + std::to_string(f) + ": face skipped: " + err.reason() + " (line " +
                                            std::to_string(err.line()) + ")");
            }
        }
    }
    model_.bodies.push_back(std::move(body));
    return static_cast<int>(model_.bodies.size()) - 1;
}

}  // namespace trimkit::io
