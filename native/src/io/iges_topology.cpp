// Topology entities of IgesReader: 144 trimmed surface (with 142 curves on
// surface), 143 bounded surface (with 141 boundaries), bare surfaces (natural
// boundary), and the B-rep 186 manifold solid / 514 shell / 510 face / 508 loop /
// 504 edge list / 502 vertex list with shared edges. Trim curves end up in the
// NURBS surface's (u,v) domain: parameter-space curves mapped from the entity's
// native parameters when the file has them and they agree with the model-space
// curve, else the model-space curve projected onto the surface (refined until
// the surface along it follows the curve, geom/project_curve_adaptive.h). On
// surfaces closed in u or v, loops may run across the seam: they are unwrapped
// and the surface extended over them (io/iges_closed_surfaces.h).
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "geom/error.h"
#include "io/iges_reader.h"
#include "geom/project_curve_adaptive.h"
#include "geom/surface_projector.h"
#include "io/iges_closed_surfaces.h"
#include "io/trim_loop_repair.h"

namespace trimkit::io {
namespace {

using geom::NurbsCurve2d;
using geom::NurbsCurve3d;
using Eigen::Vector2d;
using Eigen::Vector3d;

// A parameter curve is accepted when the surface at its ends lies within this
// fraction of the surface size from the model-space curve's ends (it catches
// wrong maps and swapped parameters, not small modelling gaps).
constexpr double kParameterCurveMatch = 1e-3;
constexpr double kResolutionsMatch = 10.0;
// Bridged loop gaps larger than this fraction of the surface size are reported.
constexpr double kReportedGap = 1e-4;
// A projected curve whose points all lie within this fraction of the domain from
// a seam (the boundary of a closed direction) runs along the seam, and may be on
// either side of it; the projector puts it on one side by its own start.
constexpr double kOnSeam = 1e-6;
// Curves given (or preferred) in model space are projected so that the surface
// along the (u,v) polyline stays within this fraction of the face's size (its
// boundary box) of the curve's foot points: 1e-5, 0.01 of the acceptance
// tolerance (1e-3 of the model's diagonal) on a face as large as the model.
constexpr double kProjectionShare = 1e-5;
// A winding loop closed along an iso-curve shorter than this share of its own
// length (but not a pole, of length 0) rounds a small end of the surface
// (PRO19800.igs: 0.216 against 50, a cone whose apex is a circle of radius 0.035
// from the file's rounding). Followed exactly, the trim runs beside that end
// circle closer than the tolerance, and tessellate_model's weld of loose faces
// (snap_boundary_vertices, close_t_junctions within T) then splits the face's
// boundary against itself without end (1133 -> 666 000 triangles, area x1.28).
// Until the weld leaves a face's own boundary alone, such faces keep
// project_curve's samples (the old boundary) with a warning.
constexpr double kNearPoleShare = 0.02;

// One piece of a boundary as the file gives it: model-space curves (in the
// face's local space, in traversal order) and/or parameter-space curves (native
// parameters, in the file's order and direction).
struct Segment {
    std::vector<NurbsCurve3d> model;
    std::vector<NurbsCurve2d> param;
    bool prefer_model = false;  // 142 preference 2: model-space curve preferred
    bool prefer_param = false;  // 142 preference 1: parameter curve preferred
    int edge = -1;           // first Model::edges index of this segment's pieces
    bool edge_reversed = false;
};

std::vector<NurbsCurve3d> reversed_chain(const std::vector<NurbsCurve3d>& c) {
    std::vector<NurbsCurve3d> r;
    for (auto it = c.rbegin(); it != c.rend(); ++it) r.push_back(it->reversed());
    return r;
}

template <int D>
Eigen::Matrix<double, D, 1> chain_start(const std::vector<geom::NurbsCurve<D>>& c) {
    return c.front().evaluate(c.front().domain().first);
}
template <int D>
Eigen::Matrix<double, D, 1> chain_end(const std::vector<geom::NurbsCurve<D>>& c) {
    return c.back().evaluate(c.back().domain().second);
}

// Largest distance from the surface images of samples of `pcs` to the
// polyline through samples of the model chain.
double chain_distance(const std::vector<NurbsCurve2d>& pcs, const std::vector<NurbsCurve3d>& model,
                      const std::function<Vector3d(const Vector2d&)>& at) {
    constexpr int kModelSamples = 32, kParamSamples = 8;
    std::vector<Vector3d> poly;
    for (const NurbsCurve3d& k : model) {
        const auto [a, b] = k.domain();
        for (int j = 0; j <= kModelSamples; ++j) poly.push_back(k.evaluate(a + (b - a) * j / kModelSamples));
    }
    double worst = 0;
    for (const NurbsCurve2d& c : pcs) {
        const auto [a, b] = c.domain();
        for (int j = 0; j <= kParamSamples; ++j) {
            const Vector3d x = at(c.evaluate(a + (b - a) * j / kParamSamples));
            double best = std::numeric_limits<double>::infinity();
            for (std::size_t i = 0; i + 1 < poly.size(); ++i) {
                const Vector3d d = poly[i + 1] - poly[i];
                const double len2 = d.squaredNorm();
                const double t = len2 > 0 ? std::clamp((x - poly[i]).dot(d) / len2, 0.0, 1.0) : 0.0;
                best = std::min(best, (poly[i] + t * d - x).norm());
            }
            worst = std::max(worst, best);
        }
    }
    return worst;
}

double surface_size(const geom::NurbsSurface& s) {
    return std::max(s.control_box().diagonal().norm(), 1e-300);
}

}  // namespace

namespace {

// Builds the coedges of one loop on surface `S` from its segments.
struct LoopBuilder {
    IgesReader& reader;
    const IgesSurface& S;
    geom::SurfaceProjector projector;
    geom::Face& face;
    int loop_number;
    double projection_tolerance;  // <= 0: project_curve's samples as they are (near_pole_fallback)
    SurfacePeriods periods;       // closed directions of S (iges_closed_surfaces.h)
    bool projected_reported = false;

    // Indices into the loop's coedges of projected curves lying along a seam.
    std::vector<std::size_t> on_seam;

    LoopBuilder(IgesReader& r, const IgesSurface& s, geom::Face& f, int n, double projection_tol)
        : reader(r), S(s), projector(s.nurbs), face(f), loop_number(n), projection_tolerance(projection_tol),
          periods(closed_periods(s.nurbs, r.closure_tolerance(s.nurbs))) {}

    // +1 / -1 when all of c's control points lie on the high / low end of the
    // closed direction `dir` (0: u, 1: v), 0 otherwise.
    int seam_side(const NurbsCurve2d& c, int dir) const {
        const auto [a, b] = dir == 0 ? S.nurbs.domain_u() : S.nurbs.domain_v();
        const double eps = kOnSeam * (b - a);
        bool low = true, high = true;
        for (const Vector2d& p : c.points()) {
            low = low && std::abs(p[dir] - a) <= eps;
            high = high && std::abs(p[dir] - b) <= eps;
        }
        return low ? -1 : high ? 1 : 0;
    }

    // True if seam curves a and b run between the same two points in opposite
    // directions along the seam in `dir` (the other coordinate, 1 - dir, reversed).
    bool runs_back(const NurbsCurve2d& a, const NurbsCurve2d& b, int dir) const {
        const auto [lo, hi] = dir == 0 ? S.nurbs.domain_v() : S.nurbs.domain_u();
        const double eps = kOnSeam * (hi - lo);
        const int o = 1 - dir;
        return std::abs(a.evaluate(a.domain().first)[o] - b.evaluate(b.domain().second)[o]) <= eps &&
               std::abs(a.evaluate(a.domain().second)[o] - b.evaluate(b.domain().first)[o]) <= eps;
    }

    // The seam side (seam_side) of the other use in `loop` of coedge k's edge, or 0.
    // Without shared edges (a 144 face) the other use is the seam curve that runs
    // back along the same stretch of the seam.
    int partner_side(const geom::Loop& loop, const std::vector<char>& flagged, std::size_t k, int dir) const {
        const geom::Coedge& e = loop.coedges[k];
        for (std::size_t j = 0; j < loop.coedges.size(); ++j) {
            if (j == k || !flagged[j]) continue;
            const geom::Coedge& other = loop.coedges[j];
            const bool same = e.edge >= 0 ? other.edge == e.edge : runs_back(e.curve, other.curve, dir);
            if (same) return seam_side(other.curve, dir);
        }
        return 0;
    }

    // Shifts c by whole periods so that its middle lies in the domain. A curve that
    // is not on a seam has one place on the surface, but the projector may give it
    // a period off (u in [-0.13, 0] for a half circle that ends on the seam from
    // below 2pi); the seam curves after it would then take the wrong side.
    void place_in_domain(NurbsCurve2d& c) const {
        const Vector2d mid = c.evaluate(0.5 * (c.domain().first + c.domain().second));
        const Vector2d shift = wrap_into_domain(S.nurbs, periods, mid) - mid;
        Vector2d whole = Vector2d::Zero();
        for (int d = 0; d < 2; ++d)
            if (periods[d] > 0.0) whole[d] = periods[d] * std::round(shift[d] / periods[d]);
        if (!whole.isZero()) c = c.transformed(Eigen::Transform<double, 2, Eigen::Affine>(Eigen::Translation2d(whole)));
    }

    // A curve projected along a seam continues the loop on the side where the
    // previous coedge ends (a seam edge used twice by one loop, as in a cylinder
    // bounded by two circles and a seam line, is on the low side once and on the
    // high side once; the projector cannot know which). Where the previous coedge
    // ends at a pole, every u there is the same point: the seam edge's other use in
    // the loop decides instead (a sphere's seam runs up to a pole and back down on
    // the other side). Run after all add()s.
    void settle_seam_sides(geom::Loop& loop) const {
        const std::size_t n = loop.coedges.size();
        if (on_seam.empty() || n < 2) return;
        std::vector<char> flagged(n, 0);
        for (std::size_t k : on_seam) flagged[k] = 1;
        for (std::size_t k = 0; k < n; ++k)
            if (!flagged[k]) place_in_domain(loop.coedges[k].curve);
        // Start after a coedge that is not on the seam, so its end is settled; a
        // loop that is all seam (a whole ball: its seam down and up) keeps its
        // first coedge's side and settles the others from it.
        std::size_t first = 0;
        while (first < n && flagged[first]) ++first;
        if (first == n) first = 0;
        for (std::size_t step = 1; step < n; ++step) {
            const std::size_t k = (first + step) % n;
            if (!flagged[k]) continue;
            geom::Coedge& e = loop.coedges[k];
            const NurbsCurve2d& prev = loop.coedges[(k + n - 1) % n].curve;
            const Vector2d prev_end = prev.evaluate(prev.domain().second);
            for (int dir = 0; dir < 2; ++dir) {
                const bool closed = dir == 0 ? projector.closed_u() : projector.closed_v();
                const int side = seam_side(e.curve, dir);
                if (!closed || side == 0) continue;
                const auto [a, b] = dir == 0 ? S.nurbs.domain_u() : S.nurbs.domain_v();
                const double here = side < 0 ? a : b, other = side < 0 ? b : a;
                if (projector.free_at(wrap_into_domain(S.nurbs, periods, prev_end), dir)) {
                    if (partner_side(loop, flagged, k, dir) != side) continue;
                } else if (std::abs(prev_end[dir] - other) >= std::abs(prev_end[dir] - here)) {
                    continue;
                }
                std::vector<Vector2d> P = e.curve.points();
                for (Vector2d& p : P) p[dir] = other;
                e.curve = NurbsCurve2d(e.curve.degree(), e.curve.knots(), std::move(P),
                                       e.curve.is_rational() ? e.curve.weights() : std::vector<double>{});
            }
        }
    }

    // The surface at uv, periodic in closed directions (a parameter curve may run
    // past the seam), clamped in the others.
    Vector3d at(const Vector2d& uv) const {
        const Vector2d w = wrap_into_domain(S.nurbs, periods, uv);
        return S.nurbs.evaluate(w.x(), w.y());
    }

    void add(const Segment& seg, geom::Loop& loop) {
        std::vector<NurbsCurve2d> pcs;
        bool use_param = !seg.param.empty() && (!seg.prefer_model || seg.model.empty());
        if (use_param) {
            for (const NurbsCurve2d& c : seg.param) {
                std::optional<NurbsCurve2d> m = reader.map_to_nurbs(S, c);
                if (!m) {
                    use_param = false;
                    break;
                }
                pcs.push_back(std::move(*m));
            }
        }
        if (use_param && !pcs.empty() && !seg.model.empty()) {
            // Orient the parameter chain like the model chain; reject it when
            // neither direction matches (a wrong map or a broken file).
            // The file's own resolution (Global field 19) also counts as agreement.
            const double tol = std::max(kParameterCurveMatch * surface_size(S.nurbs),
                                        kResolutionsMatch * reader.file().global().min_resolution);
            const Vector3d m0 = chain_start(seg.model), m1 = chain_end(seg.model);
            const Vector3d p0 = at(chain_start(pcs)), p1 = at(chain_end(pcs));
            double off = 0;
            if ((m0 - m1).norm() > tol) {
                const double fwd = std::max((p0 - m0).norm(), (p1 - m1).norm());
                const double bwd = std::max((p0 - m1).norm(), (p1 - m0).norm());
                if (bwd < fwd && bwd <= tol) {
                    std::vector<NurbsCurve2d> r;
                    for (auto it = pcs.rbegin(); it != pcs.rend(); ++it) r.push_back(it->reversed());
                    pcs = std::move(r);
                }
                off = std::min(fwd, bwd);
            }
            // A closed chain may start anywhere: compare shapes, not ends
            // (loop direction is settled later for the whole loop).
            if (off <= tol) off = chain_distance(pcs, seg.model, [&](const Vector2d& uv) { return at(uv); });
            if (off > tol) {
                const std::string n = std::to_string(loop_number);
                if (seg.prefer_param) {
                    face.warnings.push_back("trim curve " + n + ": model-space curve is off the parameter curve by " +
                                            geom::format_value(off) + "; parameter curve used as the file prefers");
                } else {
                    face.warnings.push_back("trim curve " + n + ": parameter curve is off its model-space curve by " +
                                            geom::format_value(off) + "; projected instead");
                    use_param = false;
                }
            }
        }
        if (!use_param || pcs.empty()) {
            if (seg.model.empty()) return;  // nothing usable: the loop closer bridges it
            pcs.clear();
            for (const NurbsCurve3d& k : seg.model) {
                pcs.push_back(projection_tolerance > 0.0
                                  ? geom::project_curve_adaptive(projector, k, projection_tolerance, periods.u, periods.v)
                                  : geom::project_curve(projector, k));
                if ((projector.closed_u() && seam_side(pcs.back(), 0) != 0) ||
                    (projector.closed_v() && seam_side(pcs.back(), 1) != 0))
                    on_seam.push_back(loop.coedges.size() + pcs.size() - 1);
            }
            if (!projected_reported) {
                face.warnings.push_back("trim curve " + std::to_string(loop_number) +
                                        " projected from model space");
                projected_reported = true;
            }
        }
        for (std::size_t k = 0; k < pcs.size(); ++k) {
            geom::Coedge e;
            e.curve = std::move(pcs[k]);
            if (seg.edge >= 0) {
                // Pieces of a composite edge curve are consecutive edges.
                const std::size_t n = pcs.size();
                e.edge = seg.edge + static_cast<int>(seg.edge_reversed ? n - 1 - k : k);
                e.edge_reversed = seg.edge_reversed;
            }
            loop.coedges.push_back(std::move(e));
        }
    }
};

void add_points(BoundaryHint* hint, const std::vector<NurbsCurve3d>& curves) {
    for (const auto& c : curves)
        for (const auto& p : c.points()) hint->push_back(p);
}

// The tolerance projected trim curves follow (kProjectionShare of the face's
// boundary box, or of the surface when the face has no model-space curve).
double projection_tolerance(const BoundaryHint& hint, const geom::NurbsSurface& surface) {
    Eigen::AlignedBox3d box;
    for (const Vector3d& p : hint) box.extend(p);
    const double size = box.isEmpty() ? 0.0 : box.diagonal().norm();
    return kProjectionShare * (size > 0.0 ? size : surface_size(surface));
}

// Length on the surface of a loop's coedges (sampled).
double loop_length(const geom::Loop& loop, const geom::NurbsSurface& S) {
    constexpr int kSamples = 32;
    double length = 0.0;
    for (const geom::Coedge& e : loop.coedges) {
        const auto [a, b] = e.curve.domain();
        Vector3d prev;
        for (int k = 0; k <= kSamples; ++k) {
            const Vector2d uv = e.curve.evaluate(a + (b - a) * k / kSamples);
            const Vector3d x = S.evaluate(uv.x(), uv.y());
            if (k > 0) length += (x - prev).norm();
            prev = x;
        }
    }
    return length;
}

// Loops of a face on a surface closed in u or v: coedges shifted by whole periods
// to continue each other, and the surface extended over loops that run past its
// domain (not with a natural outer boundary, which is the domain itself).
// Returns the length of the shortest iso-curve a winding loop was closed along
// that is a near-pole (above kSameFoot, below kNearPoleShare of the loop's length), or -1.
double cover_closed_surface(const IgesReader& r, geom::Face& face, bool natural_outer) {
    const double tol = r.closure_tolerance(face.surface);
    const SurfacePeriods periods = closed_periods(face.surface, tol);
    if (!periods.any()) return -1.0;
    double near_pole = -1.0;
    for (std::size_t i = 0; i < face.loops.size(); ++i) {
        geom::Loop& loop = face.loops[i];
        unwrap_loop(loop, face.surface, periods);
        if (natural_outer && i == 0) continue;
        const double iso = settle_winding(loop, face.surface, periods);
        if (iso < 0.0) continue;
        face.warnings.push_back("loop " + std::to_string(i + 1 - (natural_outer ? 1 : 0)) +
                                " winds around the closed surface; closed along its iso-curve of length " +
                                geom::format_value(iso));
        // A pole (an iso-curve of no length, kSameFoot) is not a near-pole end.
        const double length = loop_length(loop, face.surface);
        if (iso > geom::kSameFoot * length && iso < kNearPoleShare * length && (near_pole < 0.0 || iso < near_pole))
            near_pole = iso;
    }
    if (natural_outer) return near_pole;
    if (place_loops_by_largest(face.loops, periods))
        face.warnings.push_back("loops shifted by whole periods into the range of the loop that encloses them");
    shift_loops_into_domain(face.loops, face.surface, periods);
    const auto [u0, u1] = face.surface.domain_u();
    const auto [v0, v1] = face.surface.domain_v();
    if (!cover_loops(face.surface, face.loops, periods, tol)) return near_pole;
    const auto [a0, a1] = face.surface.domain_u();
    const auto [b0, b1] = face.surface.domain_v();
    face.warnings.push_back("trim loops run across the surface's seam: domain [" + geom::format_value(u0) + ", " +
                            geom::format_value(u1) + "] x [" + geom::format_value(v0) + ", " +
                            geom::format_value(v1) + "] extended to [" + geom::format_value(a0) + ", " +
                            geom::format_value(a1) + "] x [" + geom::format_value(b0) + ", " +
                            geom::format_value(b1) + "] (the surface repeats with its period)");
    return near_pole;
}

// The warning of a face whose loops are rebuilt with the coarse projection.
std::string near_pole_warning(double iso) {
    return "a model-space trim rounds a small end of the closed surface (an iso-curve " + geom::format_value(iso) +
           " long), so following it makes that end a boundary running beside the trim; projected at the coarse "
           "sample spacing instead (issue 9: the mesh weld cannot take boundaries closer than the tolerance)";
}

// The face's loops from the file's segments, as LoopBuilder makes them (with a
// natural outer loop first when `natural_outer`; loop 1 flagged outer when
// `first_is_outer`), on surfaces closed in u or v unwrapped and covered. Model-space
// trims are projected adaptively; where that rounds a near-pole end (cover_closed_surface)
// the loops are built again from project_curve's samples, with a warning.
void build_face_loops(IgesReader& r, const IgesSurface& S, const BoundaryHint& hint,
                      const std::vector<std::vector<Segment>>& loops, bool natural_outer, bool first_is_outer,
                      geom::Face& face) {
    const std::size_t warnings_before = face.warnings.size();
    auto build = [&](double projection_tol) {
        face.surface = S.nurbs;
        face.loops.clear();
        face.warnings.resize(warnings_before);
        if (natural_outer) face.loops.push_back(geom::natural_boundary_loop(S.nurbs));
        for (std::size_t i = 0; i < loops.size(); ++i) {
            geom::Loop loop;
            loop.outer = first_is_outer && i == 0;
            LoopBuilder lb(r, S, face, static_cast<int>(i + 1), projection_tol);
            for (const Segment& seg : loops[i]) lb.add(seg, loop);
            lb.settle_seam_sides(loop);
            face.loops.push_back(std::move(loop));
        }
        return cover_closed_surface(r, face, natural_outer);
    };
    if (const double iso = build(projection_tolerance(hint, S.nurbs)); iso >= 0.0) {
        build(0.0);
        face.warnings.push_back(near_pole_warning(iso));
    }
}

// Loop 1, which the file declares outer, unless another loop encloses it
// (enclosing_loop); `what` is the file's word for a loop in the warning.
void settle_outer_loop(geom::Face& face, const std::string& what) {
    if (face.loops.size() < 2) return;
    const std::size_t outer = enclosing_loop(face.loops, 0);
    if (outer == 0) return;
    face.loops[0].outer = false;
    face.loops[outer].outer = true;
    face.warnings.push_back(what + " " + std::to_string(outer + 1) + " encloses " + what +
                            " 1; taken as the outer " + what);
}

}  // namespace

// Finishes a face: closes and orients loops, applies the placement, stores it.
static int store_face(IgesReader& r, geom::Face face, const Eigen::Affine3d& T) {
    const double tol = kReportedGap * surface_size(face.surface);
    std::vector<geom::Loop> kept;
    for (std::size_t i = 0; i < face.loops.size(); ++i) {
        geom::Loop& loop = face.loops[i];
        if (!close_loop(loop, face.surface, tol, "loop " + std::to_string(i + 1), &face.warnings)) {
            if (loop.outer) {
                face.warnings.push_back("outer loop has no usable curve; natural boundary used");
                geom::Loop nat = geom::natural_boundary_loop(face.surface);
                kept.insert(kept.begin(), std::move(nat));
            } else {
                face.warnings.push_back("loop " + std::to_string(i + 1) + " has no usable curve; dropped");
            }
            continue;
        }
        kept.push_back(std::move(loop));
    }
    if (kept.empty()) kept.push_back(geom::natural_boundary_loop(face.surface));
    // Outer loop first.
    std::stable_partition(kept.begin(), kept.end(), [](const geom::Loop& l) { return l.outer; });
    for (geom::Loop& l : kept) orient_loop(l, l.outer != face.reversed);
    face.loops = std::move(kept);
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
        std::vector<std::vector<Segment>> loops;
        BoundaryHint hint;
        for (int b : boundaries) {
            std::vector<Segment> segs;
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
                Segment s;
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
                    Segment s;
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
        build_face_loops(*this, S, hint, loops, natural_outer, first_is_outer, face);
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
    std::vector<std::vector<Segment>> loops;
    BoundaryHint hint;
    for (int l : loop_des) {
        std::vector<Segment> segs;
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
            Segment s;
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
    build_face_loops(*this, S, hint, loops, false, outer_flag != 0, face);
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
                warn("D" + std::to_string(f) + ": face skipped: " + err.reason() + " (line " +
                     std::to_string(err.line()) + ")");
            }
        }
    }
    model_.bodies.push_back(std::move(body));
    return static_cast<int>(model_.bodies.size()) - 1;
}

}  // namespace trimkit::io
