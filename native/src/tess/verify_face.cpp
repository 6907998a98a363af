#include "tess/verify_face.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

#include "geom/error.h"
#include "tess/lift_trim_curve.h"
#include "tess/snap_boundary_vertices.h"
#include "tess/triangle_bvh.h"
#include "tess/unpaired_sides.h"

namespace trimkit::tess {
namespace {

// ---- The bounds ----
//
// Area. A mesh within T of the trimmed surface both ways differs from it in area by
//  (1) the strip between the mesh boundary and the exact boundary: the boundary
//      lies within T of the trim curves, so the strip is at most L·T wide-times-long
//      (L the trims' 3D length); a shared edge's points sit off the surface by the
//      file's edge gap g by design, so L·(T + g);
//  (2) the triangles' tilt against the surface: a flat triangle under a curved
//      patch misses ∫ (1/cos θ - 1) dA, θ the angle between the patch's normal and
//      the triangle's; a triangle tilted across the surface (thin triangles near a
//      pole, fans at a degenerate edge) is larger than the patch it covers by as
//      much. With θ_t the largest angle between a triangle's normal and its vertices'
//      exact normals either is at most about A_t·(1/cos θ_t - 1) (re-derived; on a
//      cylinder it is 3x the true deficit e/(3R)·A), counted kCurvatureSafety times
//      (OCC17026-1.igs at 1e-4 of the model: a mesh within 0.55 T of its surface both
//      ways, 0.17% larger than it while L·T is 0.04%, inside this term);
//  (3) the integrator's error: the fine measure's trim polygons (TrimRegion) and
//      tangencies of the trims with v = const, kAreaRelativeSlack of the area (the
//      coarse measure only filters: verify_face.h).
// A face meshed over a hole of radius r gains π r² against 2π r·T from (1): the area
// test sees holes wider than ~2T, the boundary test the rest.
//
// Boundary. The mesh's boundary follows the trim polylines, within the trim
// tolerance (T / 2) of the curves; a unified edge end may move by T and a shared
// edge sits g off: a curve point lies within T + g of the mesh boundary, and every
// boundary vertex within T + g of a curve, plus rounding.
//
// On the 29 IGES and 14 STEP files of ../shared/data/cad at tolerances of 1e-2, 1e-3
// and 1e-4 of the model (and yang trims, approximate mode at 1e-3), accepted faces
// use at most 0.47 of the area bound and 0.94 of the boundary bound
// (bm2_ec_exhaust-A.stp at 1e-4, whose edges lie 14.6 T off its faces: the gap).
constexpr double kCurvatureSafety = 2.0;
constexpr double kAreaRelativeSlack = 1e-3;
// A triangle more than 60° from a vertex's normal (at a cone's apex, a pole, a
// pinched parametrization, a fold) may differ from its patch by its own area: 1/cos θ
// - 1 is capped at 1. On OCC17026-1.igs at 1e-4 of the model, thin triangles across
// the surface's pinched lines u = 0.2, 0.8 (|Su x Sv| down to 1e-4 of its largest)
// are 40x their patches: 0.17% of the face, covered by these caps.
constexpr double kCurvatureCap = 1.0;
// A curve point off the mesh boundary is on a lobe that bounds no area when the
// region is on neither or both sides of it at this share of T across it: above the
// widest sliver repair_trim_loop drops (0.01 T) and the fine TrimRegion polygon's
// error, below any width worth meshing (a strip this narrow has less area than
// L·T of the area bound).
constexpr double kAcrossShare = 0.25;
// ... and at this share too: a face narrower than kAcrossShare T has region on neither
// side of its curves at that distance, so its points would all pass as lobes and any
// mesh of it (a ribbon 0.15 wide at T = 2 sewn shut into 2 triangles, 44 T off) pass
// the boundary test. Twice the widest sliver repair_trim_loop drops.
constexpr double kNarrowAcrossShare = 0.02;
// Curve points farther than this share of the boundary bound from the mesh boundary
// are tested for bounding no area (a lobe's points nearer than the bound would
// otherwise count, and loop_gap creep up to the bound along its base).
constexpr double kProbeShare = 0.5;
// The coarse TrimRegion samples a span at least this often.
constexpr int kMinCoarseSpanSamples = 4;
// Rounding of the bounds: a share of T, and of the face's size (coordinates ~1e6 T).
constexpr double kRoundingShare = 1e-6;
constexpr double kRoundingRelative = 1e-12;

// ---- Sampling the trim curves in 3D ----
// Intervals per piece of a coedge's curve to start with (two, so an S-shaped piece is
// halved where its middle lies on its chord), and at least per coedge. The pieces are
// trim_curve_breaks': the curve's spans cut where it crosses the surface's knot lines,
// so a straight (u,v) line across many surface spans (an iso-line edge of a terrain)
// starts with two samples per surface span, not 8 for its whole length.
constexpr int kSpanIntervals = 2, kMinCoedgeIntervals = 8;
// An interval is halved while S(c(t)) at its middle lies more than this share of T
// from its chord, at most kMaxHalvings times (1024 pieces of a starting interval),
// so the sampled polyline is within ~0.2 T of the curve: a boundary vertex on the
// trim polyline (T / 2 from the curve) measures at most ~0.7 T from it.
constexpr double kChordShare = 0.2;
constexpr int kMaxHalvings = 10;
// A coedge never gets more samples than this.
constexpr int kMaxCoedgeSamples = 20000;

std::string short_figure(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", x);
    return text;
}

std::vector<double> breaks(const std::vector<double>& U, double a, double b) {
    std::vector<double> t{a};
    for (double k : U)
        if (k > t.back() && k < b) t.push_back(k);
    t.push_back(b);
    return t;
}

// Points S(c(t)) along one coedge, first and last included, refined where the
// chord leaves the curve.
std::vector<CurveSample> sample_coedge(const geom::NurbsSurface& S, const geom::NurbsCurve2d& c,
                                       double chord_tolerance) {
    const auto [a, b] = c.domain();
    const std::vector<double> t = trim_curve_breaks(S, c);
    const int spans = static_cast<int>(t.size()) - 1;
    const int per = std::max(kSpanIntervals, (kMinCoedgeIntervals + spans - 1) / spans);
    const auto at = [&](double s) {
        const Eigen::Vector2d uv = c.evaluate(s);
        return CurveSample{s, S.evaluate(uv.x(), uv.y())};
    };
    std::vector<CurveSample> out{at(a)};
    // Depth-first halving of [t0, t1]; the sample at t0 is out.back().
    struct Piece {
        CurveSample end;
        int depth;
    };
    std::vector<Piece> stack;
    for (int s = spans - 1; s >= 0; --s)
        for (int k = per - 1; k >= 0; --k) stack.push_back({at(t[s] + (t[s + 1] - t[s]) * (k + 1) / per), 0});
    while (!stack.empty()) {
        const Piece piece = stack.back();
        stack.pop_back();
        const CurveSample mid = at(0.5 * (out.back().t + piece.end.t));
        if (piece.depth < kMaxHalvings && static_cast<int>(out.size() + stack.size()) < kMaxCoedgeSamples &&
            (mid.xyz - 0.5 * (out.back().xyz + piece.end.xyz)).norm() > chord_tolerance) {
            stack.push_back({piece.end, piece.depth + 1});
            stack.push_back({mid, piece.depth + 1});
            continue;
        }
        out.push_back(piece.end);
    }
    return out;
}

// Whether the curve c bounds the trimmed region at c(t): points `across` away from it
// in 3D on its two sides differ in membership (even-odd over the face's loops). Not
// so on a lobe where a loop runs back along itself within `across`: it encloses no
// area, repair_trim_loop drops it, and the mesh need not follow it.
bool bounds_region(const TrimRegion& region, const geom::NurbsSurface& S, const geom::NurbsCurve2d& c, double t,
                   double across) {
    const std::vector<Eigen::Vector2d> d = c.derivatives(t, 1);
    const double speed = d[1].norm();
    if (!(speed > 0.0)) return true;
    const Eigen::Vector2d n(-d[1].y() / speed, d[1].x() / speed);
    const geom::SurfaceDerivatives sd = S.derivatives(d[0].x(), d[0].y());
    const double stretch = (sd.Su * n.x() + sd.Sv * n.y()).norm();
    if (!(stretch > 0.0) || !std::isfinite(stretch)) return true;
    const Eigen::Vector2d step = (across / stretch) * n;
    return region.contains(d[0] + step) != region.contains(d[0] - step);
}

// The coarse TrimRegion's points per span: options.coarse_trim's, fewer on faces
// whose trims have many (short) spans, so a face gets about coarse_points in all.
TrimRegionOptions coarse_trim(const geom::Face& face, const VerifyFaceOptions& options) {
    int spans = 0;
    for (const geom::Loop& loop : face.loops)
        for (const geom::Coedge& coedge : loop.coedges) {
            const auto [a, b] = coedge.curve.domain();
            spans += static_cast<int>(breaks(coedge.curve.knots(), a, b).size()) - 1;
        }
    TrimRegionOptions trim = options.coarse_trim;
    trim.samples_per_span = std::clamp(options.coarse_points / std::max(spans, 1), kMinCoarseSpanSamples,
                                       std::max(kMinCoarseSpanSamples, options.coarse_trim.samples_per_span));
    return trim;
}

// A polyline set as a mesh of degenerate triangles (a, b, b), so TriangleBvh
// finds the closest point on its segments.
void add_segment(mesh::Mesh& m, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    const auto k = static_cast<std::int32_t>(m.positions.size());
    m.positions.push_back(a);
    m.positions.push_back(b);
    m.triangles.push_back({k, k + 1, k + 1});
}

// Area bound (2) of the header comment: the triangles' tilt against the surface.
double tilt_bound(const geom::NurbsSurface& S, const mesh::Mesh& m) {
    const bool normals = m.has_normals(), uvs = m.has_uvs();
    if (!normals && !uvs) return 0.0;
    std::vector<Eigen::Vector3d> n = m.normals;
    if (!normals) {
        n.resize(m.positions.size());
        for (std::size_t v = 0; v < n.size(); ++v) n[v] = S.normal(m.uvs[v].x(), m.uvs[v].y());
    }
    double tilt = 0.0;
    for (const auto& tri : m.triangles) {
        const Eigen::Vector3d c = (m.positions[tri[1]] - m.positions[tri[0]]).cross(m.positions[tri[2]] - m.positions[tri[0]]);
        const double twice = c.norm();
        if (!(twice > 0.0)) continue;
        double cos_min = 1.0;
        for (int k = 0; k < 3; ++k) {
            const double len = n[tri[k]].norm();
            cos_min = std::min(cos_min, len > 0.0 ? std::abs(c.dot(n[tri[k]])) / (twice * len) : 0.0);
        }
        tilt += 0.5 * twice * std::min(kCurvatureCap, cos_min > 0.0 ? 1.0 / cos_min - 1.0 : kCurvatureCap);
    }
    return tilt;
}

}  // namespace

FaceReference face_reference(const geom::Face& face, double tolerance, const VerifyFaceOptions& options) {
    if (!(tolerance > 0.0) || !std::isfinite(tolerance))
        throw geom::InvalidInput("verify_face: tolerance = " + geom::format_value(tolerance) +
                                 "; expected > 0 and finite");
    const geom::NurbsSurface& S = face.surface;
    FaceReference ref;
    ref.tolerance = tolerance;
    // The trim loops' curves in 3D: samples per coedge, and all as segments.
    ref.samples.resize(face.loops.size());
    for (std::size_t l = 0; l < face.loops.size(); ++l)
        for (const geom::Coedge& coedge : face.loops[l].coedges) {
            ref.samples[l].push_back(sample_coedge(S, coedge.curve, kChordShare * tolerance));
            const std::vector<CurveSample>& pts = ref.samples[l].back();
            for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
                ref.perimeter += (pts[i + 1].xyz - pts[i].xyz).norm();
                add_segment(ref.curves, pts[i].xyz, pts[i + 1].xyz);
            }
            for (const auto& p : pts) ref.extent.extend(p.xyz);
        }
    ref.area_coarse =
        trimmed_area(S, TrimRegion(face, coarse_trim(face, options)), options.coarse_cells, options.coarse_levels);
    return ref;
}

FaceVerification verify_face(const geom::Face& face, const mesh::Mesh& face_mesh,
                             const std::vector<TrimPolygon>& loops, double tolerance, int face_id,
                             const VerifyFaceOptions& options) {
    FaceReference reference = face_reference(face, tolerance, options);
    return verify_face(face, reference, face_mesh, loops, face_id, options);
}

FaceVerification verify_face(const geom::Face& face, FaceReference& ref, const mesh::Mesh& face_mesh,
                             const std::vector<TrimPolygon>& loops, int face_id, const VerifyFaceOptions& options) {
    const double tolerance = ref.tolerance;
    const geom::NurbsSurface& S = face.surface;
    const std::string prefix = "face " + std::to_string(face_id) + ": ";
    FaceVerification out;

    // Edge gap the polygons carry by design.
    Eigen::AlignedBox3d extent = ref.extent;
    for (const TrimPolygon& loop : loops)
        for (const PolylinePoint& p : loop.points) {
            out.edge_gap = std::max(out.edge_gap, (p.xyz - S.evaluate(p.uv.x(), p.uv.y())).norm());
            extent.extend(p.xyz);
        }
    out.perimeter = ref.perimeter;
    const auto& samples = ref.samples;
    const mesh::Mesh& curves = ref.curves;
    const auto fine_region = [&]() -> const TrimRegion& {
        if (!ref.fine_region) ref.fine_region.emplace(face, options.trim);
        return *ref.fine_region;
    };

    const double rounding = kRoundingShare * tolerance +
                            (extent.isEmpty() ? 0.0 : kRoundingRelative * extent.max().cwiseAbs().maxCoeff());
    out.boundary_bound = tolerance + out.edge_gap + rounding;

    // (a) Area, coarsely, then finely if the mesh is not well inside the bound.
    out.area_exact = ref.area_coarse;
    out.area_mesh = mesh::surface_area(face_mesh);
    const double tilt = kCurvatureSafety * tilt_bound(S, face_mesh);
    const auto bound = [&] {
        return out.perimeter * (tolerance + out.edge_gap) + tilt + kAreaRelativeSlack * out.area_exact +
               rounding * out.perimeter;
    };
    out.area_bound = bound();
    if (std::abs(out.area_mesh - out.area_exact) > options.recheck_share * out.area_bound) {
        if (!ref.area_fine) ref.area_fine = trimmed_area(S, fine_region(), options.area_cells, options.area_levels);
        out.area_exact = *ref.area_fine;
        out.area_bound = bound();
    }
    if (std::abs(out.area_mesh - out.area_exact) > out.area_bound) {
        out.defect = FaceDefect::kArea;
        const std::string ratio =
            out.area_exact > 0.0 ? short_figure(out.area_mesh / out.area_exact) + "x" : "not comparable to";
        out.reason = prefix + "mesh area " + ratio + " the exact trimmed area (" + short_figure(out.area_mesh) +
                     " vs " + short_figure(out.area_exact) + ", allowed +/- " + short_figure(out.area_bound) + ")";
    }
    if (face_mesh.triangles.empty()) return out;

    // (b) Boundary: flagged face-boundary edges and open sides (by position, so a
    // seam whose two sides coincide is closed unless a trim runs along it).
    mesh::Mesh boundary;
    std::vector<char> on_boundary(face_mesh.positions.size(), 0);
    for (const mesh::FlaggedEdge& e : face_mesh.edges)
        if (e.flags & mesh::kFaceBoundary) {
            add_segment(boundary, face_mesh.positions[e.v0], face_mesh.positions[e.v1]);
            on_boundary[e.v0] = on_boundary[e.v1] = 1;
        }
    const auto topology = position_triangles(face_mesh, position_groups(face_mesh));
    for (const TriangleSide& side : unpaired_sides(face_mesh, topology)) {
        const auto& tri = face_mesh.triangles[side.triangle];
        const int a = tri[side.corner], b = tri[(side.corner + 1) % 3];
        add_segment(boundary, face_mesh.positions[a], face_mesh.positions[b]);
        on_boundary[a] = on_boundary[b] = 1;
    }
    if (boundary.triangles.empty()) {
        if (out.passed()) {
            out.defect = FaceDefect::kNoBoundary;
            out.reason = prefix + "the mesh has no boundary edge to follow the trim loops";
        }
        return out;
    }

    // Curve points far from the mesh boundary count unless they bound no area
    // (bounds_region; the fine region is built only for such points).
    const TriangleBvh boundary_tree(boundary);
    out.loop_gap_loop = samples.empty() ? -1 : 0;
    for (std::size_t l = 0; l < samples.size(); ++l)
        for (std::size_t c = 0; c < samples[l].size(); ++c)
            for (const CurveSample& x : samples[l][c]) {
                TriangleBvh::Hit hit = boundary_tree.closest(x.xyz, kProbeShare * out.boundary_bound);
                if (hit.triangle < 0) {
                    const geom::NurbsCurve2d& curve = face.loops[l].coedges[c].curve;
                    if (!bounds_region(fine_region(), S, curve, x.t, kAcrossShare * tolerance) &&
                        !bounds_region(fine_region(), S, curve, x.t, kNarrowAcrossShare * tolerance)) {
                        ++out.lobe_samples;
                        continue;
                    }
                    hit = boundary_tree.closest(x.xyz);
                }
                if (hit.distance > out.loop_gap) {
                    out.loop_gap = hit.distance;
                    out.loop_gap_loop = static_cast<int>(l);
                }
            }
    if (!curves.triangles.empty()) {
        const TriangleBvh curve_tree(curves);
        for (std::size_t v = 0; v < on_boundary.size(); ++v) {
            if (!on_boundary[v]) continue;
            TriangleBvh::Hit hit = curve_tree.closest(face_mesh.positions[v], out.boundary_bound);
            if (hit.triangle < 0) hit = curve_tree.closest(face_mesh.positions[v]);
            out.boundary_gap = std::max(out.boundary_gap, hit.distance);
        }
    }
    if (!out.passed()) return out;
    const auto in_t = [&](double d) { return short_figure(d / tolerance) + " T"; };
    if (out.loop_gap > out.boundary_bound) {
        out.defect = FaceDefect::kLoopGap;
        out.reason = prefix + "trim loop " + std::to_string(out.loop_gap_loop) + " lies " +
                     short_figure(out.loop_gap) + " (" + in_t(out.loop_gap) + ") from the mesh boundary";
    } else if (out.boundary_gap > out.boundary_bound) {
        out.defect = FaceDefect::kBoundaryGap;
        out.reason = prefix + "the mesh boundary lies " + short_figure(out.boundary_gap) + " (" +
                     in_t(out.boundary_gap) + ") from every trim loop";
    }
    if (!out.passed() && out.edge_gap > kRoundingShare * tolerance)
        out.reason += " (allowed " + in_t(out.boundary_bound) + " with the edge gap)";
    return out;
}

}  // namespace trimkit::tess
