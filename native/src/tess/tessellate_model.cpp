#include "tess/tessellate_model.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <mutex>
#include <numeric>
#include <optional>
#include <tuple>

#include "geom/error.h"
#include "geom/flatten_instances.h"
#include "mesh/deadline.h"
#include "mesh/open_edges.h"
#include "mesh/parallel_for.h"
#include "mesh/parallel_sort.h"
#include "mesh/weld_vertices.h"
#include "tess/approximate_trim_curve.h"
#include "tess/area_budget.h"
#include "tess/cell_area_loss.h"
#include "tess/close_t_junctions.h"
#include "tess/fill_sliver_holes.h"
#include "tess/pcurve_edge_gap.h"
#include "tess/repair_trim_loop.h"
#include "tess/sew_free_coedges.h"
#include "tess/share_edge_points.h"
#include "tess/snap_boundary_vertices.h"
#include "tess/tessellate_face.h"
#include "tess/trim_area_loss.h"
#include "tess/verify_face.h"

namespace trimkit::tess {
namespace {

using Clock = std::chrono::steady_clock;

// Trim points closer than this fraction of the face's (u,v) domain diagonal are
// one point when joining and repairing loops (far above double rounding of the
// parameters, far below any trim segment the approximation makes).
constexpr double kSnapUvRelative = 1e-9;
// Models with shared edges meet exactly along edges and at their vertices (edge ends
// are unified, unify_edge_ends), so their snap (within kWeldShare T) only mops up
// what the file's topology misses; loose trimmed surfaces close the gaps between
// their own trim polylines, each within its trim tolerance of its curve.
// Consecutive trim points closer than this fraction of the tolerance (in 3D) are one
// point: joints of coedges that meet up to rounding (1e-12 apart) would otherwise
// leave zero-length boundary segments that no face on the other side matches.
constexpr double kDuplicatePointShare = 1e-6;
// Vertices of one face at one position whose uvs differ by more than this fraction of
// the domain diagonal lie on a seam or a pole: they stay separate vertices.
constexpr double kSplitUvShare = 1e-3;
// Pieces of a self-crossing trim loop narrower than this share of the tolerance are
// dropped (repair_trim_loop): the gap they leave is narrower still.
constexpr double kSliverWidthShare = 0.01;
// An edge whose first face's p-curve strays farther than this share of the
// tolerance from its 3D curve is approximated on its second face instead when that
// one follows the curve at least twice as closely (pcurve_edge_gap.h).
constexpr double kEdgeGapShare = 0.1;
// A shared edge's chords keep back the gap between its 3D curve and the kept face's trim,
// up to this share of their tolerance.
constexpr double kEdgeGapReserve = 0.5;
// A sewn edge (sew_free_coedges.h, within 2 kWeldShare T at its test points) whose
// faces lie farther apart than this share of T along its polyline is unsewn.
constexpr double kSewnGapLimit = 0.3;
// Holes of the joined mesh at most this many sides long and narrower than the trims'
// own tolerance (below what the trim polylines can tell apart; what repair_trim_loop
// drops and the crossings it leaves) are filled (fill_sliver_holes).
constexpr int kSliverHoleSides = 64;
// A part whose chords lose (or gain) more than kAreaShare of its mesh's area
// (area_budget.h: thin parts, or long trim chords that bow in 3D) has its faces
// that lose most meshed again with finer trims and cells, down to 1 / kMinFaceScale,
// for at most kAreaRounds rounds, until it is within kAreaMargin x kAreaShare; the
// pass whose worst part loses least is kept. Issue 9 accepts 0.2 % of the area
// against OCCT's own measure; ours agrees with it to about 0.01 % (OCCT's exact
// areas of the shared STEP files).
constexpr double kAreaShare = 1.5e-3;
constexpr double kAreaMargin = 0.8;
constexpr double kMinFaceScale = 1.0 / 64.0;
constexpr int kAreaRounds = 4;
// A round that leaves the worst part under this share of kAreaShare overshot: up to
// kAreaBackOffPasses passes bisect back towards the budget (back_off_to_budget).
constexpr double kAreaUndershoot = 0.5;
// A round that adds more than kAreaRoundGrowth of the triangles and cuts the worst part's
// loss by less than kAreaGainPerGrowth x that growth stops the rounds: where the chords
// are not what loses the area (OCC17026-1.igs at 1e-4: 0.178 % -> 0.174 % for 223k ->
// 834k triangles), finer meshes only grow. Only a first round that loses more goes on to
// the next (a torus's loss jumps with the pieces revolution_error cuts its cells into:
// torus_hole_on_seams_brep.igs at 0.01 of its diagonal, 0.43 % then 0.56 %, then
// 0.15 %); later ones stop there (bm2_ec_exhaust-A.stp at 1e-4 went on to 292k
// triangles, its loss not the chords').
constexpr double kAreaRoundGrowth = 0.5, kAreaGainPerGrowth = 0.1;
constexpr int kAreaBackOffPasses = 2;
// Samples per trim curve and per side of the (u,v) grid for model_diagonal.
constexpr int kDiagonalCurveSamples = 16, kDiagonalGridSamples = 12;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

double uv_diagonal(const geom::NurbsSurface& S) {
    const auto [u0, u1] = S.domain_u();
    const auto [v0, v1] = S.domain_v();
    return std::hypot(u1 - u0, v1 - v0);
}

struct CoedgeRef {
    int face = -1, loop = -1, coedge = -1;
};

struct FaceOutput {
    mesh::Mesh mesh;
    std::string error;
    // The verification's figures when the mesh was made and checked (else absent).
    std::optional<FaceVerification> verification;
    std::vector<std::string> warnings;
    FaceTimings timings;
    double trim_seconds = 0.0;
    double verify_seconds = 0.0;
    double trim_loss = 0.0;  // area the trim chords lose (trim_area_loss)
    double cell_loss = 0.0;  // area the triangles lose inside the trims (cell_area_loss)
    bool timed_out = false;  // stopped by options.face_timeout (error says where)
    double seconds = 0.0;    // wall time of all the face's attempts
};

// Phase 1's shared edges, for the faces.
struct SharedEdges {
    const std::vector<CoedgeRef>& first;  // the coedge that approximated each edge
    const std::vector<std::optional<TrimPolyline>>& polyline;  // its polyline
    const std::vector<std::vector<Eigen::Vector3d>>& points;  // the edge's points, in edge direction
};

// What a pass leaves for the next, so that a round of the area budget meshes again
// only the faces whose trims, cells or edges changed; its output is the same as a
// pass from scratch (each face's mesh depends on nothing else).
struct PassState {
    FaceScales scales;
    std::vector<double> edge_scale;                         // per edge; 0 when not approximated
    std::vector<std::optional<TrimPolyline>> raw_polyline;  // each edge as approximated
    std::vector<std::optional<TrimPolyline>> polyline;      // after unify_edge_ends
    std::vector<std::vector<Eigen::Vector3d>> points;
    std::vector<FaceOutput> outputs;
    // Each face's verify_face reference, made when the face is first verified: it
    // measures the exact face, not its mesh, so every pass shares it.
    std::vector<std::optional<FaceReference>> references;
};

bool same_polyline(const std::optional<TrimPolyline>& a, const std::optional<TrimPolyline>& b) {
    if (a.has_value() != b.has_value()) return false;
    if (!a) return true;
    if (a->edge != b->edge || a->points.size() != b->points.size()) return false;
    for (size_t i = 0; i < a->points.size(); ++i)
        if (a->points[i].uv != b->points[i].uv || a->points[i].xyz != b->points[i].xyz ||
            a->points[i].t != b->points[i].t)
            return false;
    return true;
}

// How a face is meshed: the first attempt as asked; a rejected face once more with
// the other 3D trim method and, where the loops were repaired, without dropping
// slivers. The retry approximates the face's shared edges itself too (else a B-rep
// face, all of whose coedges are shared, would be meshed from the same polygons
// again): its points there are the other method's, within the trim tolerance of the
// same curve, and the boundary snap closes what it can of the seam.
struct FaceAttempt {
    TrimMethod method = TrimMethod::kBezier3d;
    bool own_shared_edges = false;
    double sliver_share = kSliverWidthShare;
    std::string name;  // for the report: "with yang trims"
};

bool cancelled(const TessellationOptions& options) {
    return options.cancel && options.cancel->load(std::memory_order_relaxed);
}

// options.progress as faces are done: one call at a time, the fraction rising.
class FaceProgress {
public:
    FaceProgress(std::function<void(double)> report, int faces) : report_(std::move(report)), faces_(faces) {}
    // Marks one face done when it goes out of scope (however the face ends).
    class Done {
    public:
        explicit Done(FaceProgress& p) : p_(p) {}
        ~Done() { p_.face_done(); }
        Done(const Done&) = delete;
        Done& operator=(const Done&) = delete;

    private:
        FaceProgress& p_;
    };

private:
    void face_done() {
        if (!report_) return;
        const std::lock_guard<std::mutex> lock(mutex_);
        try {
            report_(static_cast<double>(++done_) / faces_);
        } catch (...) {
            report_ = nullptr;  // a failing reporter is dropped; the tessellation goes on
        }
    }
    std::function<void(double)> report_;
    int faces_;
    int done_ = 0;
    std::mutex mutex_;
};

FaceAttempt first_attempt(const TessellationOptions& options) {
    return {options.trim_method, false, kSliverWidthShare, ""};
}

FaceAttempt second_attempt(const TessellationOptions& options) {
    const bool bezier = options.trim_method == TrimMethod::kBezier3d;
    return {bezier ? TrimMethod::kYang : TrimMethod::kBezier3d, true, 0.0,
            bezier ? "with yang trims" : "with bezier3d trims"};
}

std::string without_face_prefix(const std::string& what, int f) {
    const std::string prefix = "face " + std::to_string(f) + ": ";
    return what.rfind(prefix, 0) == 0 ? what.substr(prefix.size()) : what;
}

// Flags face-boundary edges (open, or between different faces) and sharp ones
// (triangle normals differing by more than `angle`).
void flag_edges(mesh::Mesh& mesh, double angle, int threads) {
    // Edges by position (vertices are per face): triangle sides sorted by their
    // position groups, in triangle order within an edge; each flagged edge names the
    // vertices of its first triangle.
    const std::vector<std::int32_t> group = position_groups(mesh, false, threads);
    struct Side {
        int lo, hi, triangle, va, vb;
    };
    std::vector<Side> sides;
    sides.reserve(3 * mesh.triangles.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const int va = mesh.triangles[t][k], vb = mesh.triangles[t][(k + 1) % 3];
            const int a = group[va], b = group[vb];
            if (a != b) sides.push_back({std::min(a, b), std::max(a, b), static_cast<int>(t), va, vb});
        }
    mesh::parallel_sort(
        sides.begin(), sides.end(), threads,
        [](const Side& x, const Side& y) { return std::tie(x.lo, x.hi) < std::tie(y.lo, y.hi); }, true);
    auto normal = [&](int t) {
        const auto& tri = mesh.triangles[t];
        return Eigen::Vector3d((mesh.positions[tri[1]] - mesh.positions[tri[0]])
                                   .cross(mesh.positions[tri[2]] - mesh.positions[tri[0]]));
    };
    const double cos_angle = std::cos(angle);
    mesh.edges.clear();
    for (size_t i = 0; i < sides.size();) {
        size_t j = i + 1;
        while (j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi) ++j;
        std::uint8_t flags = 0;
        if (j - i != 2) {
            flags |= mesh::kFaceBoundary;
        } else if (mesh.face_ids[sides[i].triangle] != mesh.face_ids[sides[i + 1].triangle]) {
            flags |= mesh::kFaceBoundary;
            const Eigen::Vector3d n0 = normal(sides[i].triangle), n1 = normal(sides[i + 1].triangle);
            const double len = n0.norm() * n1.norm();
            if (len > 0.0 && n0.dot(n1) < cos_angle * len) flags |= mesh::kSharp;
        }
        if (flags) mesh.edges.push_back({sides[i].va, sides[i].vb, flags});
        i = j;
    }
}

// Drops interior points of a polyline within `distance` (3D) of the previous kept
// point; the ends stay (they are the coedge's vertices).
void drop_duplicate_points(TrimPolyline& polyline, double distance) {
    auto& pts = polyline.points;
    if (pts.size() < 3) return;
    std::vector<PolylinePoint> kept{pts.front()};
    for (std::size_t i = 1; i + 1 < pts.size(); ++i)
        if ((pts[i].xyz - kept.back().xyz).norm() > distance) kept.push_back(pts[i]);
    if (kept.size() > 1 && (pts.back().xyz - kept.back().xyz).norm() <= distance) kept.pop_back();
    kept.push_back(pts.back());
    pts = std::move(kept);
}

// One model vertex per edge end: the ends of edges that meet in some loop (a
// coedge's end and the next coedge's start) are unified, by union-find over the
// keys 2e (start of edge e) and 2e+1 (its end), onto the point of the smallest key
// of their class when all lie within `reach` of it. Both faces of every edge then
// see identical vertex positions, and the mesh closes without a distance weld.
void unify_edge_ends(const geom::Model& model, std::vector<std::vector<Eigen::Vector3d>>& edge_points,
                     std::vector<std::optional<TrimPolyline>>& edge_polyline,
                     const std::vector<bool>& reversed_on_first, double reach) {
    const int ne = static_cast<int>(model.edges.size());
    std::vector<int> parent(2 * ne);
    std::iota(parent.begin(), parent.end(), 0);
    const auto find = [&](int k) {
        while (parent[k] != k) k = parent[k] = parent[parent[k]];
        return k;
    };
    const auto usable = [&](int e) { return e >= 0 && e < ne && edge_points[e].size() >= 2; };
    for (const geom::Face& face : model.faces)
        for (const geom::Loop& loop : face.loops) {
            const std::size_t n = loop.coedges.size();
            for (std::size_t c = 0; c < n; ++c) {
                const geom::Coedge& a = loop.coedges[c];
                const geom::Coedge& b = loop.coedges[(c + 1) % n];
                if (!usable(a.edge) || !usable(b.edge)) continue;
                const int end_a = 2 * a.edge + (a.edge_reversed ? 0 : 1);
                const int start_b = 2 * b.edge + (b.edge_reversed ? 1 : 0);
                const int ra = find(end_a), rb = find(start_b);
                if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
            }
        }
    const auto point = [&](int k) -> Eigen::Vector3d& {
        auto& pts = edge_points[k / 2];
        return k % 2 == 0 ? pts.front() : pts.back();
    };
    std::vector<std::vector<int>> classes(2 * ne);
    for (int k = 0; k < 2 * ne; ++k)
        if (usable(k / 2)) classes[find(k)].push_back(k);
    for (int r = 0; r < 2 * ne; ++r) {
        if (classes[r].size() < 2) continue;
        const Eigen::Vector3d target = point(r);
        bool near = true;
        for (int k : classes[r]) near = near && (point(k) - target).norm() <= reach;
        if (!near) continue;
        for (int k : classes[r]) {
            point(k) = target;
            // The first face's polyline runs along the coedge: its ends in traversal order.
            auto& poly = edge_polyline[k / 2];
            if (!poly || poly->points.empty()) continue;
            const bool at_start = (k % 2 == 0) != reversed_on_first[k / 2];
            (at_start ? poly->points.front() : poly->points.back()).xyz = target;
        }
    }
}

// Snaps open-boundary vertices within weld_tol, closes T-junctions, fills sliver holes
// up to sliver_width. On a degenerate boundary (snap_boundary_vertices.h,
// close_t_junctions.h: piled-up vertices, whose joining grows with the square of the
// pile) the stage that meets it stops, the hole filling (a shortest-cycle search per
// open side) is skipped, and a warning says so.
void join_faces(mesh::Mesh& m, double weld_tol, double sliver_width, int threads, std::vector<std::string>& warnings) {
    bool piled = false, crowded = false;
    snap_boundary_vertices(m, weld_tol, &piled, threads);
    if (piled)
        warnings.push_back("joining the faces: more than " + std::to_string(kMaxSnapPairsPerEnd) +
                           " open-edge vertices per open-edge vertex lie within the weld tolerance (a degenerate "
                           "boundary); the faces were not snapped together");
    close_t_junctions(m, weld_tol, &crowded, threads);
    if (crowded)
        warnings.push_back("joining the faces: more than " + std::to_string(kMaxJunctionTestsPerSide) +
                           " boundary vertices per open edge lie near the open edges (a degenerate boundary); "
                           "T-junctions were closed only in part");
    if (piled || crowded)
        warnings.push_back("joining the faces: sliver holes not filled (degenerate boundary)");
    else
        fill_sliver_holes(m, sliver_width, kSliverHoleSides, threads);
}

FailedFace failed_face(int f, const FaceOutput& out) {
    FailedFace failed;
    failed.face = f;
    failed.reason = out.error;
    failed.seconds = out.seconds;
    if (out.timed_out) {
        failed.defect = "timeout";
        return failed;
    }
    if (!out.verification || out.verification->passed()) return failed;
    const FaceVerification& v = *out.verification;
    switch (v.defect) {
        case FaceDefect::kArea: failed.defect = "area"; break;
        case FaceDefect::kLoopGap: failed.defect = "trim_loop"; break;
        case FaceDefect::kBoundaryGap: failed.defect = "boundary"; break;
        case FaceDefect::kNoBoundary: failed.defect = "no_boundary"; break;
        case FaceDefect::kNone: break;
    }
    failed.area_mesh = v.area_mesh;
    failed.area_exact = v.area_exact;
    failed.area_bound = v.area_bound;
    failed.boundary_gap = std::max(v.loop_gap, v.boundary_gap);
    failed.boundary_bound = v.boundary_bound;
    return failed;
}

int boundary_edge_count(const mesh::Mesh& mesh) {
    int count = 0;
    for (const mesh::FlaggedEdge& e : mesh.edges) count += (e.flags & mesh::kFaceBoundary) != 0;
    return count;
}

// Edges without a 3D curve (sewn ones, sew_free_coedges.h) whose faces lie farther
// apart along them than kEdgeGapShare T get their points midway between the two
// faces (move_edge_points_midway, share_edge_points.h), so each face's boundary is
// half their gap off it; the first face's polyline takes the moved points. An edge
// with a 3D curve keeps the points of the face that follows the curve: the file says
// where the boundary is. Faces more than T apart are reported.
void meet_midway(const geom::Model& model, const std::vector<int>& shared, const std::vector<CoedgeRef>& first,
                 const std::vector<CoedgeRef>& second, const TessellationOptions& options,
                 std::vector<std::vector<Eigen::Vector3d>>& edge_points,
                 std::vector<std::optional<TrimPolyline>>& edge_polyline, const std::vector<bool>& reversed_on_first,
                 int threads, std::vector<std::string>& warnings) {
    const double least_gap = kEdgeGapShare * options.tolerance;
    std::vector<double> moved_gap(model.edges.size(), 0.0);
    mesh::parallel_for(static_cast<int>(shared.size()), threads, [&](int k) {
        const int e = shared[k];
        if (model.edges[e].curve || second[e].face < 0 || !edge_polyline[e] || edge_points[e].size() < 2) return;
        const geom::Face& face = model.faces[second[e].face];
        try {
            const SharedEdgePolyline mapped = share_edge_points(
                face.surface, face.loops[second[e].loop].coedges[second[e].coedge], edge_points[e]);
            if (mapped.max_gap <= least_gap) return;
            if (mapped.max_gap > kSewnGapLimit * options.tolerance) {
                // Sewn on the pairing test's points, farther apart between them: each
                // face approximates its own trim again, and the join meets them.
                edge_polyline[e].reset();
                edge_points[e].clear();
                return;
            }
            move_edge_points_midway(edge_points[e], mapped.feet);
            std::vector<PolylinePoint>& points = edge_polyline[e]->points;
            const size_t n = points.size();
            for (size_t i = 0; i < n; ++i) points[i].xyz = edge_points[e][reversed_on_first[e] ? n - 1 - i : i];
            moved_gap[e] = mapped.max_gap;
        } catch (const std::exception&) {
            // The second face maps the points itself and reports what fails.
        }
    });
    for (int e : shared)
        if (moved_gap[e] > options.tolerance)
            warnings.push_back("edge " + std::to_string(e) + ": faces " + std::to_string(first[e].face) + " and " +
                               std::to_string(second[e].face) + " lie up to " + geom::format_value(moved_gap[e]) +
                               " apart along it (more than the tolerance); the mesh runs midway between them");
}

// The report of a shared edge whose points lie `gap` from face f's surface, more than
// the face tolerance T leaves beside the edge's chords (surface_tolerance).
std::string edge_off_face_warning(int f, int e, double gap, double tolerance) {
    const std::string t = geom::format_value(tolerance);
    return "face " + std::to_string(f) + ": edge " + std::to_string(e) + " lies " + geom::format_value(gap) +
           " from the surface (more than the tolerance " + t + " leaves beside the edge's chords, " +
           geom::format_value(trim_tolerance({tolerance})) + ": the file's edge is that far off this face, and the "
           "mesh follows the edge, so the face's mesh may lie up to their sum from it)";
}

// Marks trim points whose chords keep their cell crossings (remove_crossings.h): the
// polylines the join welds by position to another face's, where a crossing is a point
// to meet (a coedge the face approximates alone while its edge has another face; a
// repaired loop, whose cuts and dropped lobes leave its boundary off its neighbours':
// removed there, bug22869_Spring.igs at 1e-3 had 23 open edges instead of 9).
void keep_crossings(std::vector<PolylinePoint>& points) {
    for (PolylinePoint& p : points) p.keep_crossings = true;
}

// Meshes face f one way (`attempt`), welds it and verifies the mesh. Any failure
// (an exception, no triangles, a rejected mesh) is out.error, naming the face.
// trim_scale, cell_scale: the shares of their tolerance the face's own trims and its
// cells get (area_budget.h).
// deadline: the face's (options.face_timeout, over all its attempts); once it has
// passed, the attempt stops with out.timed_out set.
FaceOutput mesh_face(const geom::Model& model, int f, const TessellationOptions& options, double trim_scale,
                     double cell_scale, const SharedEdges& edges, const FaceAttempt& attempt,
                     mesh::Deadline& deadline, std::optional<FaceReference>& reference) {
    const double trim_tol = trim_scale * trim_tolerance(options);
    const geom::Face& face = model.faces[f];
    FaceOutput out;
    try {
        const auto trim_start = Clock::now();
        const double snap_uv = kSnapUvRelative * uv_diagonal(face.surface);
        std::vector<TrimPolygon> polygons;
        for (size_t l = 0; l < face.loops.size(); ++l) {
            const geom::Loop& loop = face.loops[l];
            std::vector<TrimPolyline> polylines;
            for (size_t c = 0; c < loop.coedges.size(); ++c) {
                deadline.check_now("trim curve approximation");
                const geom::Coedge& coedge = loop.coedges[c];
                const int e = coedge.edge;
                const bool has_edge = !attempt.own_shared_edges && e >= 0 &&
                                      e < static_cast<int>(model.edges.size()) && edges.polyline[e].has_value();
                const CoedgeRef first = has_edge ? edges.first[e] : CoedgeRef{};
                if (has_edge && first.face == f && first.loop == static_cast<int>(l) &&
                    first.coedge == static_cast<int>(c)) {
                    polylines.push_back(*edges.polyline[e]);
                } else if (has_edge) {
                    SharedEdgePolyline mapped = share_edge_points(face.surface, coedge, edges.points[e]);
                    // The mesh follows the edge, its chords up to the trim tolerance off it:
                    // beyond what T leaves beside them the face's mesh may leave T.
                    if (mapped.max_gap > surface_tolerance(options))
                        out.warnings.push_back(edge_off_face_warning(f, e, mapped.max_gap, options.tolerance));
                    polylines.push_back(std::move(mapped.polyline));
                } else {
                    // A coedge of an edge that is not shared here is welded to its other
                    // face's own approximation.
                    const TrimSimplification simplification =
                        e >= 0 ? TrimSimplification::kPoints : TrimSimplification::kHulls;
                    polylines.push_back(approximate_trim_curve(face.surface, coedge.curve, trim_tol, attempt.method,
                                                               &deadline, simplification));
                    polylines.back().edge = e;
                    drop_duplicate_points(polylines.back(), kDuplicatePointShare * options.tolerance);
                    if (e >= 0) keep_crossings(polylines.back().points);
                }
            }
            LoopRepairReport report;
            const TrimPolygon joined = join_trim_loop(polylines, loop.outer, snap_uv, &report);
            const bool region_left = region_left_of(joined, loop.outer);
            for (size_t c = 0; c < polylines.size(); ++c)
                out.trim_loss += trim_area_loss(face.surface, loop.coedges[c].curve, polylines[c], region_left);
            for (TrimPolygon& p : repair_trim_loop(joined, snap_uv, &report, face.reversed, &face.surface,
                                                   attempt.sliver_share * options.tolerance, &deadline)) {
                if (report.changed()) keep_crossings(p.points);
                polygons.push_back(std::move(p));
            }
            if (report.changed())
                out.warnings.push_back("face " + std::to_string(f) + ": trim loop " + std::to_string(l) +
                                       " repaired (" + std::to_string(report.crossings) + " crossings, " +
                                       std::to_string(report.dropped) + " slivers dropped" +
                                       (report.reoriented ? ", reoriented" : "") + ")");
        }
        out.trim_seconds = seconds_since(trim_start);
        TessellationOptions face_options = options;
        face_options.trim_method = attempt.method;
        face_options.tolerance = cell_scale * options.tolerance;
        out.mesh = tessellate_face(face, polygons, face_options, f, &out.timings, &deadline);
        deadline.check_now("welding the face");
        // Near-duplicates within the face (a grid crossing 1e-13 from a trim
        // point) become one vertex, dropping the zero-area slivers between them;
        // a seam's or a pole's vertices (same position, uvs far apart) stay
        // split. Faces are never merged by index: each keeps its own uvs.
        mesh::WeldOptions near;
        near.tolerance = kDuplicatePointShare * options.tolerance;
        near.keep_split_uvs = true;
        near.split_uv_distance = kSplitUvShare * uv_diagonal(face.surface);
        mesh::weld_vertices(out.mesh, near);
        if (out.mesh.triangle_count() == 0) {
            out.error = "face " + std::to_string(f) + ": no triangles (the trimmed region is empty or degenerate)";
            return out;
        }
        const auto verify_start = Clock::now();
        deadline.check_now("verification");
        if (!reference) reference = face_reference(face, options.tolerance);
        out.verification = verify_face(face, *reference, out.mesh, polygons, f);
        out.verify_seconds = seconds_since(verify_start);
        deadline.check_now("verification");
        if (!out.verification->passed()) out.error = out.verification->reason;
        else if (face.surface_kind != "plane") out.cell_loss = cell_area_loss(face.surface, out.mesh);

    } catch (const mesh::DeadlineExceeded& e) {
        out.error = "face " + std::to_string(f) + ": timeout: " + e.what();
        out.timed_out = true;
    } catch (const geom::NumericalFailure& e) {
        out.error = e.what();
    } catch (const geom::InvalidInput& e) {
        out.error = e.what();
    } catch (const std::bad_alloc&) {
        out.error = "face " + std::to_string(f) + ": out of memory";
    } catch (const std::exception& e) {
        out.error = "face " + std::to_string(f) + ": internal error: " + e.what();
    }
    if (!out.error.empty()) out.mesh = mesh::Mesh();
    return out;
}

// The report of an edge whose 3D curve lies `gap` from its faces' trims (> T).
std::string edge_curve_gap_warning(int edge, int face_a, int face_b, double gap, double tolerance) {
    return "edge " + std::to_string(edge) + " (faces " + std::to_string(face_a) + " and " + std::to_string(face_b) +
           "): the file's 3D curve lies " + geom::format_value(gap) + " from the faces' trims (more than the " +
           "tolerance " + geom::format_value(tolerance) +
           ": the mesh follows the faces, so a measure that takes the edge's curve for their boundary, as Open "
           "CASCADE's does within the edge's own tolerance, finds up to that there)";
}

// One pass over the model, face f's trims and cells at scales.trim[f] and
// scales.cell[f] times their share of the tolerance (a shared edge's trims at the
// smaller of its faces'); *areas gets each meshed face's area and the areas its
// chords lose (zero for the others). `state`: the previous pass's (empty for the
// first), replaced by this one's. Faces are meshed to options.tolerance and gathered
// in face order, not yet joined (join_pass).
TessellationResult tessellate_pass(const geom::Model& model, const TessellationOptions& options,
                                   const FaceScales& scales, std::vector<FaceArea>* areas, PassState& state) {
    PassState previous = std::move(state);  // its unchanged faces' outputs are moved on
    const bool has_previous = !previous.outputs.empty();
    state = PassState{scales, std::vector<double>(model.edges.size(), 0.0), {}, {}, {}, {},
                      std::move(previous.references)};
    state.references.resize(model.faces.size());
    TessellationResult result;
    result.faces = static_cast<int>(model.faces.size());
    areas->assign(model.faces.size(), FaceArea{});
    result.tolerance = options.tolerance;
    const int threads = mesh::resolve_threads(options.threads);
    const std::vector<double>& trim_scale = scales.trim;

    // Phase 1: each shared edge approximated once, on the first face (in face order)
    // that uses it.
    auto start = Clock::now();
    std::vector<CoedgeRef> first(model.edges.size()), second(model.edges.size());
    std::vector<int> shared;
    for (size_t f = 0; f < model.faces.size(); ++f)
        for (size_t l = 0; l < model.faces[f].loops.size(); ++l)
            for (size_t c = 0; c < model.faces[f].loops[l].coedges.size(); ++c) {
                const int e = model.faces[f].loops[l].coedges[c].edge;
                if (e < 0 || e >= static_cast<int>(model.edges.size()) || second[e].face >= 0) continue;
                const CoedgeRef ref{static_cast<int>(f), static_cast<int>(l), static_cast<int>(c)};
                if (first[e].face < 0) {
                    first[e] = ref;
                    shared.push_back(e);
                } else {
                    second[e] = ref;
                }
            }
    // The face whose p-curve follows the edge's 3D curve gives the edge its points.
    std::vector<double> curve_gap(model.edges.size(), 0.0);  // reported below when over T
    std::vector<double> kept_gaps(model.edges.size(), 0.0);  // the kept face's coarse gap
    mesh::parallel_for(static_cast<int>(shared.size()), threads, [&](int k) {
        const int e = shared[k];
        if (second[e].face < 0 || !model.edges[e].curve) return;
        const auto gap = [&](const CoedgeRef& r) {
            const geom::Face& face = model.faces[r.face];
            return pcurve_edge_gap(face.surface, face.loops[r.loop].coedges[r.coedge].curve, *model.edges[e].curve);
        };
        const double first_gap = gap(first[e]);
        double kept_gap = first_gap;
        if (first_gap > kEdgeGapShare * options.tolerance) {
            const double second_gap = gap(second[e]);
            if (2.0 * second_gap < first_gap) {
                std::swap(first[e], second[e]);
                kept_gap = second_gap;
            }
        }
        kept_gaps[e] = kept_gap;
        // Neither face follows the file's edge curve (its trims agree, its curve does
        // not): the mesh follows the faces, and says so.
        if (kept_gap > options.tolerance) {
            const geom::Face& face = model.faces[first[e].face];
            curve_gap[e] = pcurve_edge_gap_fine(
                face.surface, face.loops[first[e].loop].coedges[first[e].coedge].curve, *model.edges[e].curve);
        }
    });
    const double user_tolerance = options.tolerance / (1.0 - kWeldShare);  // the pass gets face_tolerance
    for (int e : shared)
        if (curve_gap[e] > user_tolerance)
            result.warnings.push_back(edge_curve_gap_warning(e, first[e].face, second[e].face, curve_gap[e],
                                                             user_tolerance));
    std::vector<std::optional<TrimPolyline>> edge_polyline(model.edges.size());
    std::vector<std::vector<Eigen::Vector3d>> edge_points(model.edges.size());
    mesh::parallel_for(static_cast<int>(shared.size()), threads, [&](int k) {
        const int e = shared[k];
        const geom::Face& face = model.faces[first[e].face];
        const geom::Coedge& coedge = face.loops[first[e].loop].coedges[first[e].coedge];
        double scale = trim_scale[first[e].face];
        if (second[e].face >= 0) scale = std::min(scale, trim_scale[second[e].face]);
        state.edge_scale[e] = scale;
        if (has_previous && previous.edge_scale[e] == scale) {
            edge_polyline[e] = previous.raw_polyline[e];
            return;
        }
        try {
            // Its own limit (each face has its own too): an edge over it is left to its faces,
            // which then stop at theirs and report it.
            mesh::Deadline deadline(options.face_timeout, options.cancel);
            // The edge's own curve lies up to kept_gaps[e] from the face's trim (a measure
            // that takes the curve for the faces' boundary, as OCCT's does, sees both):
            // the chords keep that much of their tolerance back, up to half of it.
            const double edge_tolerance = scale * trim_tolerance(options);
            const double chord_tolerance = edge_tolerance - std::min(kept_gaps[e], kEdgeGapReserve * edge_tolerance);
            TrimPolyline polyline =
                approximate_trim_curve(face.surface, coedge.curve, chord_tolerance, options.trim_method, &deadline);
            polyline.edge = e;
            edge_points[e] = edge_points_from(polyline, coedge.edge_reversed);
            edge_polyline[e] = std::move(polyline);
        } catch (const std::exception&) {
            // The faces using the edge approximate it themselves (and report failures).
        }
    });
    state.raw_polyline = edge_polyline;
    std::vector<bool> reversed_on_first(model.edges.size(), false);
    for (int e : shared) {
        const geom::Face& face = model.faces[first[e].face];
        reversed_on_first[e] = face.loops[first[e].loop].coedges[first[e].coedge].edge_reversed;
        if (edge_polyline[e]) {
            drop_duplicate_points(*edge_polyline[e], kDuplicatePointShare * options.tolerance);
            edge_points[e] = edge_points_from(*edge_polyline[e], reversed_on_first[e]);
        }
    }
    meet_midway(model, shared, first, second, options, edge_points, edge_polyline, reversed_on_first, threads,
                result.warnings);
    unify_edge_ends(model, edge_points, edge_polyline, reversed_on_first, options.tolerance);
    const double edge_seconds = seconds_since(start);
    // A face is meshed as in the previous pass when its scales and all its edges' points are.
    const auto unchanged = [&](int f) {
        if (!has_previous || previous.scales.trim[f] != scales.trim[f] || previous.scales.cell[f] != scales.cell[f])
            return false;
        for (const geom::Loop& loop : model.faces[f].loops)
            for (const geom::Coedge& coedge : loop.coedges) {
                const int e = coedge.edge;
                if (e < 0 || e >= static_cast<int>(model.edges.size())) continue;
                if (!same_polyline(previous.polyline[e], edge_polyline[e]) || previous.points[e] != edge_points[e])
                    return false;
            }
        return true;
    };

    // Phase 2: faces, each verified (verify_face) and retried once another way if
    // its mesh is rejected.
    start = Clock::now();
    const SharedEdges edges{first, edge_polyline, edge_points};
    std::vector<FaceOutput> outputs(model.faces.size());
    FaceProgress progress(has_previous ? std::function<void(double)>() : options.progress,
                          static_cast<int>(model.faces.size()));
    mesh::parallel_for(static_cast<int>(model.faces.size()), threads, [&](int f) {
        const FaceProgress::Done done(progress);
        FaceOutput& out = outputs[f];
        if (cancelled(options)) {
            out.error = "face " + std::to_string(f) + ": cancelled";
            return;
        }
        if (unchanged(f)) {
            out = std::move(previous.outputs[f]);
            out.timings = FaceTimings{};
            out.trim_seconds = out.verify_seconds = 0.0;
            return;
        }
        mesh::Deadline deadline(options.face_timeout, options.cancel);
        std::optional<FaceReference>& reference = state.references[f];
        out = mesh_face(model, f, options, trim_scale[f], scales.cell[f], edges, first_attempt(options), deadline,
                        reference);
        out.seconds = deadline.elapsed();
        if (out.error.empty() || out.timed_out) return;
        FaceOutput retry =
            mesh_face(model, f, options, trim_scale[f], scales.cell[f], edges, second_attempt(options), deadline,
                      reference);
        const double trim_seconds = out.trim_seconds + retry.trim_seconds;
        const double verify_seconds = out.verify_seconds + retry.verify_seconds;
        FaceTimings timings = retry.timings;
        timings.surface += out.timings.surface;
        timings.trim += out.timings.trim;
        timings.triangulate += out.timings.triangulate;
        if (retry.error.empty()) {
            retry.warnings.insert(retry.warnings.begin(), out.error + "; retried " + second_attempt(options).name +
                                                              ", which passed");
            out = std::move(retry);
        } else {
            out.error += "; retried " + second_attempt(options).name + ": " + without_face_prefix(retry.error, f);
        }
        out.trim_seconds = trim_seconds;
        out.verify_seconds = verify_seconds;
        out.timings = timings;
        out.timed_out = retry.timed_out;
        out.seconds = deadline.elapsed();
    });
    const double face_wall = seconds_since(start);
    if (cancelled(options)) throw TessellationCancelled("tessellate_model: cancelled");

    // Gather in face order.
    double trim_sum = 0.0, surface_sum = 0.0, triangulate_sum = 0.0, verify_sum = 0.0;
    for (size_t f = 0; f < outputs.size(); ++f) {
        FaceOutput& out = outputs[f];
        trim_sum += out.trim_seconds + out.timings.trim;
        surface_sum += out.timings.surface;
        triangulate_sum += out.timings.triangulate;
        result.warnings.insert(result.warnings.end(), out.warnings.begin(), out.warnings.end());
        verify_sum += out.verify_seconds;
        if (!out.error.empty()) {
            result.failed_faces.push_back(failed_face(static_cast<int>(f), out));
            continue;
        }
        if (out.mesh.triangle_count() == 0) continue;
        // verify_face measured the accepted mesh's area already.
        const double area = out.verification ? out.verification->area_mesh : mesh::surface_area(out.mesh);
        (*areas)[f] = FaceArea{area, out.trim_loss, out.cell_loss,
                              static_cast<int>(out.mesh.triangle_count()), boundary_edge_count(out.mesh)};
        ++result.faces_meshed;
        mesh::append(result.mesh, out.mesh);
    }
    state.polyline = std::move(edge_polyline);
    state.points = std::move(edge_points);
    state.outputs = std::move(outputs);
    const double sum = trim_sum + surface_sum + triangulate_sum + verify_sum;
    if (sum > 0.0) {
        result.seconds.trim = edge_seconds + face_wall * trim_sum / sum;
        result.seconds.surface = face_wall * surface_sum / sum;
        result.seconds.triangulate = face_wall * triangulate_sum / sum;
        result.seconds.verify = face_wall * verify_sum / sum;
    } else {
        result.seconds.trim = edge_seconds + face_wall;
    }

    return result;
}

// Joins the faces of a pass's mesh by position, each part (`groups`: part_groups) on
// its own: snaps open-boundary vertices within `weld_distance` (never collapsing a
// triangle, never moving a vertex by more than it), closes T-junctions between faces,
// flags edges, counts open edges. Vertices stay per face. Parts are not joined to each
// other: two parts that touch (a nut on a bracket) have their own closed boundaries,
// and snapping one onto the other left T-junctions inside each (as1-oc-214-mat.stp).
// Only the pass that is kept is joined (the area budget compares the faces' own meshes).
void join_pass(TessellationResult& result, const TessellationOptions& options, double weld_distance,
               const FaceScales& scales, const std::vector<std::vector<int>>& groups) {
    const auto start = Clock::now();
    const std::vector<double>& trim_scale = scales.trim;
    const double least_scale =
        trim_scale.empty() ? 1.0 : *std::min_element(trim_scale.begin(), trim_scale.end());
    const int threads = mesh::resolve_threads(options.threads);
    const auto join = [&](mesh::Mesh& part, std::vector<std::string>& warnings) {
        join_faces(part, weld_distance, least_scale * trim_tolerance(options), threads, warnings);
        flag_edges(part, options.angle, threads);
        return count_position_open_edges(part, threads);
    };
    if (groups.size() <= 1) {  // one part: joined in place
        result.open_edges = result.mesh.vertex_count() > 0 ? join(result.mesh, result.warnings) : 0;
        result.seconds.weld = seconds_since(start);
        return;
    }
    std::vector<int> group_of_face(scales.trim.size(), 0);
    for (size_t g = 0; g < groups.size(); ++g)
        for (int f : groups[g]) group_of_face[f] = static_cast<int>(g);
    std::vector<mesh::Mesh> parts = split_by_face_group(result.mesh, group_of_face, static_cast<int>(groups.size()));
    result.mesh = mesh::Mesh{};
    result.open_edges = 0;
    std::vector<std::string> warnings;
    for (mesh::Mesh& part : parts) {
        if (part.vertex_count() == 0) continue;
        result.open_edges += join(part, warnings);
        mesh::append(result.mesh, part);
    }
    std::sort(warnings.begin(), warnings.end());
    warnings.erase(std::unique(warnings.begin(), warnings.end()), warnings.end());
    result.warnings.insert(result.warnings.end(), warnings.begin(), warnings.end());
    result.seconds.weld = seconds_since(start);
}

// Adds the seconds of `pass` to `total`.
void add_seconds(TessellationTimings& total, const TessellationTimings& pass) {
    total.trim += pass.trim;
    total.surface += pass.surface;
    total.triangulate += pass.triangulate;
    total.weld += pass.weld;
    total.verify += pass.verify;
}

// The area rounds cut scales by the loss they predict, and a polyline's points change
// in steps, so a round can land far under the budget with many more triangles than it
// needs (torus_hole_on_seams_faces.igs: 0.154 % -> 0.034 %, +50 %). Then the scales are
// bisected (geometric mean per face) between the kept pass's and the last pass's over
// the budget, kAreaBackOffPasses times; a pass within the budget with fewer triangles
// is kept.
void back_off_to_budget(const geom::Model& model, const TessellationOptions& face_options,
                        const std::vector<std::vector<int>>& groups, FaceScales over_budget, PassState& state,
                        FaceScales& scale, TessellationResult& result, double& worst) {
    for (int pass = 0; pass < kAreaBackOffPasses && !cancelled(face_options); ++pass) {
        FaceScales midway = scale;
        bool changed = false;
        for (size_t f = 0; f < model.faces.size(); ++f) {
            midway.trim[f] = std::sqrt(scale.trim[f] * over_budget.trim[f]);
            midway.cell[f] = std::sqrt(scale.cell[f] * over_budget.cell[f]);
            changed = changed || midway.trim[f] != scale.trim[f] || midway.cell[f] != scale.cell[f];
        }
        if (!changed) return;
        std::vector<FaceArea> midway_areas;
        TessellationResult candidate = tessellate_pass(model, face_options, midway, &midway_areas, state);
        add_seconds(result.seconds, candidate.seconds);
        const double candidate_worst = worst_loss_share(groups, midway_areas);
        if (candidate_worst > kAreaShare || candidate.failed_faces.size() > result.failed_faces.size()) {
            over_budget = midway;
            continue;
        }
        if (candidate.mesh.triangle_count() >= result.mesh.triangle_count()) return;
        candidate.seconds = result.seconds;
        result = std::move(candidate);
        worst = candidate_worst;
        scale = midway;
    }
}

// The model meshed as it is (tessellate_model after sewing).
TessellationResult tessellate_sewn(const geom::Model& model, const TessellationOptions& options) {
    const double weld_distance = kWeldShare * options.tolerance;
    TessellationOptions face_options = options;
    face_options.tolerance = face_tolerance(options);
    const std::vector<std::vector<int>> groups = area_groups(model, options.area_per_body);
    const std::vector<double> ones(model.faces.size(), 1.0);
    FaceScales scale{ones, ones};
    std::vector<FaceArea> areas;
    PassState state;
    TessellationResult result = tessellate_pass(model, face_options, scale, &areas, state);

    double worst = worst_loss_share(groups, areas);
    const double first_worst = worst;
    FaceScales next = scale;
    FaceScales over_budget = scale;  // the scales of the last kept pass over the budget
    std::vector<char> tightened(groups.size(), 0);
    for (int round = 0; round < kAreaRounds && worst > kAreaShare && !cancelled(options); ++round) {
        const std::vector<int> over =
            tighten_to_area_budget(groups, areas, kAreaShare, kAreaMargin, kMinFaceScale, next);
        if (over.empty()) break;
        for (int g : over) tightened[g] = 1;
        std::vector<FaceArea> finer_areas;
        TessellationResult finer = tessellate_pass(model, face_options, next, &finer_areas, state);
        add_seconds(result.seconds, finer.seconds);
        if (finer.failed_faces.size() > result.failed_faces.size()) break;
        // A polyline's points change in steps, so a round that loses no less keeps
        // the lower scales for the next.
        areas = finer_areas;

        const double finer_worst = worst_loss_share(groups, finer_areas);
        const double growth =
            double(finer.mesh.triangle_count()) / double(std::max<std::size_t>(1, result.mesh.triangle_count())) - 1.0;
        const bool first_lost_more = round == 0 && !(finer_worst < worst);
        if (growth > kAreaRoundGrowth && !first_lost_more && finer_worst > worst * (1.0 - kAreaGainPerGrowth * growth))
            break;
        if (!(finer_worst < worst)) continue;
        finer.seconds = result.seconds;
        result = std::move(finer);
        worst = finer_worst;
        over_budget = scale;
        scale = next;
    }
    if (worst < kAreaUndershoot * kAreaShare && worst < first_worst && !cancelled(options))
        back_off_to_budget(model, face_options, groups, over_budget, state, scale, result, worst);
    if (worst < first_worst) {
        int faces = 0;
        for (size_t f = 0; f < model.faces.size(); ++f) faces += scale.trim[f] < 1.0 || scale.cell[f] < 1.0;
        result.warnings.push_back("the chords of " + std::to_string(std::count(tightened.begin(), tightened.end(), 1)) +
                                  " part(s) lost or gained up to " + geom::format_value(100.0 * first_worst) +
                                  " % of their area; " + std::to_string(faces) +
                                  " face(s) meshed again with finer trims and cells (now " +
                                  geom::format_value(100.0 * worst) + " %)");
    }
    join_pass(result, face_options, weld_distance, scale, part_groups(model));
    result.tolerance = options.tolerance;
    return result;
}

bool has_free_coedges(const geom::Model& model) {
    for (const geom::Face& face : model.faces)
        for (const geom::Loop& loop : face.loops)
            for (const geom::Coedge& coedge : loop.coedges)
                if (coedge.edge < 0) return true;
    return false;
}

}  // namespace

TessellationResult tessellate_model(const geom::Model& model, const TessellationOptions& options) {
    validate(options);
    // Coedges the file does not share but that run along each other become shared
    // edges (sew_free_coedges.h), on a copy of the model. Their points run midway
    // between the two faces (meet_midway), so pairs up to 2 x kWeldShare T apart
    // leave each face's boundary within the join's reach of it.
    if (has_free_coedges(model)) {
        geom::Model sewn = model;
        const int threads = mesh::resolve_threads(options.threads);
        if (sew_free_coedges(sewn, 2.0 * kWeldShare * options.tolerance, threads).pairs > 0)
            return tessellate_sewn(sewn, options);
    }
    return tessellate_sewn(model, options);
}

namespace {

// Points of `face` sampled along its trim loops and on a grid inside them (even-odd
// rule in (u,v)), the box around them.
Eigen::AlignedBox3d sampled_face_box(const geom::Face& face) {
    Eigen::AlignedBox3d box;
    const geom::NurbsSurface& S = face.surface;
    std::vector<std::vector<Eigen::Vector2d>> polygons;
    Eigen::AlignedBox2d uv_box;
    for (const geom::Loop& loop : face.loops) {
        std::vector<Eigen::Vector2d> polygon;
        for (const geom::Coedge& coedge : loop.coedges) {
            const auto [t0, t1] = coedge.curve.domain();
            for (int k = 0; k < kDiagonalCurveSamples; ++k) {
                const Eigen::Vector2d uv = coedge.curve.evaluate(t0 + (t1 - t0) * k / kDiagonalCurveSamples);
                if (!uv.allFinite()) continue;
                polygon.push_back(uv);
                uv_box.extend(uv);
                const Eigen::Vector3d p = S.evaluate(uv.x(), uv.y());
                if (p.allFinite()) box.extend(p);
            }
        }
        polygons.push_back(std::move(polygon));
    }
    if (uv_box.isEmpty()) return box;
    for (int i = 0; i <= kDiagonalGridSamples; ++i)
        for (int j = 0; j <= kDiagonalGridSamples; ++j) {
            const Eigen::Vector2d uv =
                uv_box.min() + uv_box.sizes().cwiseProduct(Eigen::Vector2d(i, j) / kDiagonalGridSamples);
            bool in = false;
            for (const auto& poly : polygons)
                for (size_t a = 0, n = poly.size(), b = n - 1; a < n; b = a++)
                    if ((poly[a].y() > uv.y()) != (poly[b].y() > uv.y()) &&
                        uv.x() < poly[a].x() + (uv.y() - poly[a].y()) * (poly[b].x() - poly[a].x()) /
                                                   (poly[b].y() - poly[a].y()))
                        in = !in;
            if (!in) continue;
            const Eigen::Vector3d p = S.evaluate(uv.x(), uv.y());
            if (p.allFinite()) box.extend(p);
        }
    return box;
}

}  // namespace

double model_diagonal(const geom::Model& model, int threads) {
    if (!model.instances.empty()) return model_diagonal(geom::flatten_instances(model), threads);
    // Faces on the threads; a union of boxes is the same in any order.
    std::vector<Eigen::AlignedBox3d> boxes(model.faces.size());
    mesh::parallel_for(static_cast<int>(model.faces.size()), mesh::resolve_threads(threads),
                       [&](int f) { boxes[f] = sampled_face_box(model.faces[f]); });
    Eigen::AlignedBox3d box;
    for (const Eigen::AlignedBox3d& b : boxes)
        if (!b.isEmpty()) box.extend(b);
    return box.isEmpty() ? 0.0 : box.diagonal().norm();
}

}  // namespace trimkit::tess
