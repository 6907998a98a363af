#include "io/face_loops.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "geom/error.h"
#include "geom/project_curve_adaptive.h"
#include "geom/surface_projector.h"
#include "io/closed_surface_loops.h"
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

// Builds the coedges of one loop on surface `S` from its segments.
struct LoopBuilder {
    const FaceLoopsContext& context;
    const geom::NurbsSurface& S;
    geom::SurfaceProjector projector;
    geom::Face& face;
    int loop_number;
    double projection_tolerance;  // <= 0: project_curve's samples as they are (near_pole_fallback)
    SurfacePeriods periods;       // closed directions of S (closed_surface_loops.h)
    bool projected_reported = false;

    // Indices into the loop's coedges of projected curves lying along a seam.
    std::vector<std::size_t> on_seam;

    LoopBuilder(const FaceLoopsContext& c, const geom::NurbsSurface& s, geom::Face& f, int n, double projection_tol)
        : context(c), S(s), projector(s), face(f), loop_number(n), projection_tolerance(projection_tol),
          periods(closed_periods(s, c.closure_tolerance)) {}

    // +1 / -1 when all of c's control points lie on the high / low end of the
    // closed direction `dir` (0: u, 1: v), 0 otherwise.
    int seam_side(const NurbsCurve2d& c, int dir) const {
        const auto [a, b] = dir == 0 ? S.domain_u() : S.domain_v();
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
        const auto [lo, hi] = dir == 0 ? S.domain_v() : S.domain_u();
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
        const Vector2d shift = wrap_into_domain(S, periods, mid) - mid;
        Vector2d whole = Vector2d::Zero();
        for (int d = 0; d < 2; ++d)
            if (periods[d] > 0.0) whole[d] = periods[d] * std::round(shift[d] / periods[d]);
        if (!whole.isZero()) c = c.translated(whole);
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
                const auto [a, b] = dir == 0 ? S.domain_u() : S.domain_v();
                const double here = side < 0 ? a : b, other = side < 0 ? b : a;
                // Where the previous coedge ends at a pole, the next one's start decides
                // when it is settled and off the pole (a sphere's octant: down its seam to
                // the pole, where the loop turns), else the seam edge's other use.
                const NurbsCurve2d& next = loop.coedges[(k + 1) % n].curve;
                const Vector2d next_start = next.evaluate(next.domain().first);
                const auto at_pole = [&](const Vector2d& uv) {
                    return projector.free_at(wrap_into_domain(S, periods, uv), dir);
                };
                const bool settled_next = !flagged[(k + 1) % n] && !at_pole(next_start);
                const Vector2d& meet = at_pole(prev_end) && settled_next ? next_start : prev_end;
                if (at_pole(meet)) {
                    if (partner_side(loop, flagged, k, dir) != side) continue;
                } else if (std::abs(meet[dir] - other) >= std::abs(meet[dir] - here)) {
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
        const Vector2d w = wrap_into_domain(S, periods, uv);
        return S.evaluate(w.x(), w.y());
    }

    void add(const BoundarySegment& seg, geom::Loop& loop) {
        std::vector<NurbsCurve2d> pcs;
        bool use_param = !seg.param.empty() && (!seg.prefer_model || seg.model.empty());
        if (use_param) {
            for (const NurbsCurve2d& c : seg.param) {
                std::optional<NurbsCurve2d> m =
                    context.map_to_nurbs ? context.map_to_nurbs(c) : std::optional<NurbsCurve2d>();
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
            const double tol = std::max(kParameterCurveMatch * surface_size(S),
                                        kResolutionsMatch * context.resolution);
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
            }
            if (!projected_reported) {
                face.warnings.push_back("trim curve " + std::to_string(loop_number) +
                                        " projected from model space");
                projected_reported = true;
            }
        }
        for (std::size_t k = 0; k < pcs.size(); ++k) {
            // A curve along a seam, projected or the file's (a SEAM_CURVE's two PCURVEs may
            // both map onto one side), takes the side the loop needs (settle_seam_sides).
            if ((projector.closed_u() && seam_side(pcs[k], 0) != 0) ||
                (projector.closed_v() && seam_side(pcs[k], 1) != 0))
                on_seam.push_back(loop.coedges.size());
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
double cover_closed_surface(const FaceLoopsContext& context, geom::Face& face, bool natural_outer) {
    const double tol = context.closure_tolerance;
    const SurfacePeriods periods = closed_periods(face.surface, tol);
    if (!periods.any()) return -1.0;
    double near_pole = -1.0;
    for (std::size_t i = 0; i < face.loops.size(); ++i) {
        geom::Loop& loop = face.loops[i];
        unwrap_loop(loop, face.surface, periods);
        if (natural_outer && i == 0) continue;
        if (close_loop_along_its_pole(loop, face.surface, periods))
            face.warnings.push_back("loop " + std::to_string(i + 1 - (natural_outer ? 1 : 0)) +
                                    " closed by its edge along the pole, which the file leaves out");
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
    if (natural_outer) {
        if (!place_natural_seam(face.loops, face.surface, periods)) return near_pole;
    } else {
        if (join_winding_loops(face.loops, periods))
            face.warnings.push_back("two loops winding around the closed surface joined into one across its seam");
        else if (close_winding_loop_at_pole(face.loops, face.surface, periods, face.reversed))
            face.warnings.push_back("a loop winding around the closed surface closed at its pole");
        if (place_loops_by_largest(face.loops, periods))
            face.warnings.push_back("loops shifted by whole periods into the range of the loop that encloses them");
        shift_loops_into_domain(face.loops, face.surface, periods);
    }
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

}  // namespace

double closure_tolerance(const geom::NurbsSurface& s, double resolution) {
    constexpr double kClosedRelative = 1e-7, kClosedResolutionCap = 1e-4;
    const double size = s.control_box().diagonal().norm();
    return std::max(kClosedRelative * size, std::min(resolution, kClosedResolutionCap * size));
}

std::vector<NurbsCurve3d> reversed_chain(const std::vector<NurbsCurve3d>& c) {
    std::vector<NurbsCurve3d> r;
    for (auto it = c.rbegin(); it != c.rend(); ++it) r.push_back(it->reversed());
    return r;
}

void add_points(BoundaryHint* hint, const std::vector<NurbsCurve3d>& curves) {
    for (const auto& c : curves)
        for (const auto& p : c.points()) hint->push_back(p);
}

void build_face_loops(const geom::NurbsSurface& S, const FaceLoopsContext& context, const BoundaryHint& hint,
                      const std::vector<std::vector<BoundarySegment>>& loops, bool natural_outer, bool first_is_outer,
                      geom::Face& face) {
    const std::size_t warnings_before = face.warnings.size();
    auto build = [&](double projection_tol) {
        face.surface = S;
        face.loops.clear();
        face.warnings.resize(warnings_before);
        if (natural_outer) face.loops.push_back(geom::natural_boundary_loop(S));
        for (std::size_t i = 0; i < loops.size(); ++i) {
            geom::Loop loop;
            loop.outer = first_is_outer && i == 0;
            LoopBuilder lb(context, S, face, static_cast<int>(i + 1), projection_tol);
            for (const BoundarySegment& seg : loops[i]) lb.add(seg, loop);
            lb.settle_seam_sides(loop);
            face.loops.push_back(std::move(loop));
        }
        return cover_closed_surface(context, face, natural_outer);
    };
    if (const double iso = build(projection_tolerance(hint, S)); iso >= 0.0) {
        build(0.0);
        face.warnings.push_back(near_pole_warning(iso));
    }
}

bool holes_of_whole_surface(const geom::NurbsSurface& S, const geom::Face& face) {
    const SurfacePeriods periods = closed_periods(S, closure_tolerance(S, 0.0));
    if (!periods.any() || face.loops.empty()) return false;
    const double size = surface_size(S);
    for (int d = 0; d < 2; ++d) {
        if (periods[d] > 0.0) continue;
        const auto [a, b] = d == 0 ? S.domain_u() : S.domain_v();
        Eigen::Vector2d at(0.5 * (S.domain_u().first + S.domain_u().second),
                           0.5 * (S.domain_v().first + S.domain_v().second));
        for (const double end : {a, b}) {
            at[d] = end;
            if (!geom::parameter_is_free(S, at, 1 - d, size)) return false;  // a boundary, not a pole
        }
    }
    for (const geom::Loop& loop : face.loops) {
        if (loop.coedges.empty()) return false;
        for (int d = 0; d < 2; ++d)
            if (periods[d] > 0.0 && winding(loop, d, periods[d]) != 0) return false;
        if ((signed_area(loop) < 0.0) == face.reversed) return false;
    }
    return true;
}

void settle_outer_loop(geom::Face& face, const std::string& what) {
    if (face.loops.size() < 2) return;
    const std::size_t outer = enclosing_loop(face.loops, 0);
    if (outer == 0) return;
    face.loops[0].outer = false;
    face.loops[outer].outer = true;
    face.warnings.push_back(what + " " + std::to_string(outer + 1) + " encloses " + what +
                            " 1; taken as the outer " + what);
}

void close_face_loops(geom::Face& face) {
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
}

}  // namespace trimkit::io
