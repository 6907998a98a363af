#include "tess/tessellate_face.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <optional>
#include <set>

#include "geom/error.h"
#include "tess/collapsed_side.h"
#include "tess/flattened_cell.h"
#include "tess/kd_subdivision.h"
#include "tess/remove_crossings.h"
#include "tess/snap_trims_to_cell_lines.h"
#include "tess/surface_evaluator.h"
#include "mesh/triangulate_polygon.h"
#include "tess/trim_cells.h"

namespace trimkit::tess {
namespace {

using Clock = std::chrono::steady_clock;

// The cell grid reaches this fraction of the trim box beyond it on every side, so
// no trim point lies on the grid's outer boundary (cells are half-open).
constexpr double kBoxMargin = 1e-9;
// Trim coordinates within this share of the margin of a cell line go onto it
// (snap_trims_to_cell_lines): below the margin, so none reaches the grid's boundary.
constexpr double kSnapShare = 0.5;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

double signed_area(const TrimPolygon& loop) {
    double area = 0.0;
    const auto& p = loop.points;
    for (size_t i = 0, n = p.size(); i < n; ++i) {
        const Eigen::Vector2d& a = p[i].uv;
        const Eigen::Vector2d& b = p[(i + 1) % n].uv;
        area += a.x() * b.y() - b.x() * a.y();
    }
    return 0.5 * area;
}

std::string prefix(int face_id) { return "face " + std::to_string(face_id) + ": "; }

mesh::Mesh tessellate(const geom::Face& face, const std::vector<TrimPolygon>& input,
                      const TessellationOptions& options, int face_id, FaceTimings& timings,
                      mesh::Deadline* deadline) {
    // Loops: finite, at least 3 points, oriented as their flag says.
    std::vector<TrimPolygon> loops;
    Eigen::AlignedBox2d box;
    for (size_t l = 0; l < input.size(); ++l) {
        const TrimPolygon& loop = input[l];
        for (size_t i = 0; i < loop.points.size(); ++i)
            if (!loop.points[i].uv.allFinite() || !loop.points[i].xyz.allFinite())
                throw geom::InvalidInput(prefix(face_id) + "trim loop " + std::to_string(l) +
                                         " point " + std::to_string(i) + " is not finite");
        if (loop.points.size() < 3) continue;
        loops.push_back(loop);
        const double area = signed_area(loops.back());
        if ((loop.outer && area < 0.0) || (!loop.outer && area > 0.0))
            std::reverse(loops.back().points.begin(), loops.back().points.end());
        for (const PolylinePoint& p : loop.points) box.extend(p.uv);
    }
    mesh::Mesh mesh;
    if (loops.empty()) return mesh;
    const Eigen::Vector2d size = box.sizes();
    if (!(size.x() > 0.0) || !(size.y() > 0.0))
        throw geom::NumericalFailure(prefix(face_id) + "trim loops have zero extent in (u,v)");
    const Eigen::Vector2d margin = kBoxMargin * Eigen::Vector2d::Constant(size.maxCoeff());
    box.min() -= margin;
    box.max() += margin;
    snap_trims_to_knot_lines(loops, face.surface, kSnapShare * margin.x());

    auto start = Clock::now();
    // Cells no trim meets hold only points of S; cells a trim meets also hold the
    // crossings, off S by up to their chord's offset: tessellation_options.h.
    // Surfaces of revolution with a line or circle meridian get their exact bound.
    const std::optional<RevolutionShape> shape = revolution_shape(face.surface, face.surface_kind);
    const CellGrid grid =
        kd_subdivision(face.surface, box, interior_tolerance(options), surface_tolerance(options),
                       options.tolerance, loops, options.mode, shape ? &*shape : nullptr, deadline);
    timings.surface += seconds_since(start);

    start = Clock::now();
    snap_trims_to_cell_lines(loops, grid, kSnapShare * margin.x());
    const TrimmedCells trimmed = trim_cells(grid, loops, deadline);
    timings.trim += seconds_since(start);

    start = Clock::now();
    std::vector<Eigen::Vector2d> uv(trimmed.vertices.size());
    for (size_t i = 0; i < uv.size(); ++i) uv[i] = trimmed.vertices[i].uv;
    std::vector<std::array<int, 3>> triangles;
    // Cells on a side the surface collapses to a point: triangulated about it (collapsed_side.h).
    const CollapsedSides collapsed = collapsed_sides(face.surface);
    std::array<std::vector<Eigen::Vector2d>, 4> polar;
    // 3D points of trimmed cells' vertices, as the mesh will have them (trim points
    // keep their xyz), filled on demand.
    std::vector<Eigen::Vector3d> xyz(uv.size());
    std::vector<char> placed(uv.size(), 0);
    auto place = [&](const std::vector<int>& ring) {
        for (int i : ring) {
            if (placed[i]) continue;
            const TrimmedVertex& v = trimmed.vertices[i];
            xyz[i] = v.on_trim ? v.xyz : face.surface.evaluate(v.uv.x(), v.uv.y());
            placed[i] = 1;
        }
    };
    for (const CellPolygon& polygon : trimmed.polygons) {
        mesh::check_deadline(deadline, "triangulation");
        const int side = touched_collapsed_side(face.surface, collapsed, uv, polygon.outer);
        if (side >= 0 && polar[side].empty()) polar[side] = polar_about_side(face.surface, side, uv);
        auto cell_triangles =
            mesh::triangulate_polygon(side >= 0 ? polar[side] : uv, polygon.outer, polygon.holes, deadline);
        if (!polygon.whole_cell) {
            // Trimmed cells: a triangle thin in (u,v) may face backwards in 3D (flattened_cell.h).
            place(polygon.outer);
            for (const auto& hole : polygon.holes) place(hole);
            if (has_backward_triangle(face.surface, uv, xyz, cell_triangles)) {
                auto flat = triangulate_in_3d_plane(face.surface, uv, xyz, polygon.outer, polygon.holes, deadline);
                if (!flat.empty()) cell_triangles = std::move(flat);
            }
        }
        triangles.insert(triangles.end(), cell_triangles.begin(), cell_triangles.end());
    }

    // Crossings removed where the bound allows (remove_crossings.h); the trimmed cells'
    // vertices, all a crossing's triangles have, are placed.
    CrossingMesh reduced{std::move(uv), std::move(xyz), std::vector<char>(trimmed.vertices.size()),
                         std::move(triangles), trimmed.trim_edges};
    for (size_t i = 0; i < trimmed.vertices.size(); ++i) reduced.crossing[i] = trimmed.vertices[i].crossing;
    remove_crossings(face.surface, shape ? &*shape : nullptr, options.mode, reduced, interior_tolerance(options),
                     options.tolerance, deadline);
    uv = std::move(reduced.uv);
    triangles = std::move(reduced.triangles);

    // Used vertices, numbered in (v, u) order so evaluation runs along rows.
    std::vector<int> used;
    {
        std::vector<char> flag(uv.size(), 0);
        for (const auto& t : triangles)
            for (int v : t) flag[v] = 1;
        for (size_t i = 0; i < flag.size(); ++i)
            if (flag[i]) used.push_back(static_cast<int>(i));
    }
    std::sort(used.begin(), used.end(), [&](int a, int b) {
        return uv[a].y() != uv[b].y() ? uv[a].y() < uv[b].y() : uv[a].x() < uv[b].x();
    });
    std::vector<int> index(uv.size(), -1);
    for (size_t k = 0; k < used.size(); ++k) index[used[k]] = static_cast<int>(k);

    const double sign = face.reversed ? -1.0 : 1.0;
    SurfaceEvaluator evaluator(face.surface);
    mesh.positions.resize(used.size());
    mesh.normals.resize(used.size());
    mesh.uvs.resize(used.size());
    for (size_t k = 0; k < used.size(); ++k) {
        mesh::check_deadline(deadline, "evaluation");
        const TrimmedVertex& vertex = trimmed.vertices[used[k]];
        Eigen::Vector3d S, Su, Sv;
        evaluator.evaluate(vertex.uv.x(), vertex.uv.y(), S, Su, Sv);
        const Eigen::Vector3d n = sign * evaluator.normal(vertex.uv.x(), vertex.uv.y(), Su, Sv);
        mesh.positions[k] = vertex.on_trim ? vertex.xyz : S;
        mesh.normals[k] = n;
        mesh.uvs[k] = vertex.uv;
        if (!mesh.positions[k].allFinite() || !n.allFinite())
            throw geom::NumericalFailure(prefix(face_id) + "non-finite position or normal at (u,v) = (" +
                                         geom::format_value(vertex.uv.x()) + ", " +
                                         geom::format_value(vertex.uv.y()) + ")");
    }
    mesh.triangles.reserve(triangles.size());
    for (const auto& t : triangles) {
        std::array<std::int32_t, 3> tri{index[t[0]], index[t[1]], index[t[2]]};
        if (face.reversed) std::swap(tri[1], tri[2]);
        mesh.triangles.push_back(tri);
    }
    mesh.face_ids.assign(mesh.triangles.size(), face_id);
    std::set<std::pair<int, int>> boundary;
    for (const auto& e : reduced.trim_edges) {
        const int a = index[e[0]], b = index[e[1]];
        if (a < 0 || b < 0 || a == b) continue;
        boundary.emplace(std::min(a, b), std::max(a, b));
    }
    for (const auto& [a, b] : boundary) mesh.edges.push_back({a, b, mesh::kFaceBoundary});
    timings.triangulate += seconds_since(start);
    return mesh;
}

}  // namespace

mesh::Mesh tessellate_face(const geom::Face& face, const std::vector<TrimPolygon>& loops,
                           const TessellationOptions& options, int face_id,
                           FaceTimings* timings, mesh::Deadline* deadline) {
    validate(options);
    FaceTimings local;
    try {
        return tessellate(face, loops, options, face_id, timings ? *timings : local, deadline);
    } catch (const geom::NumericalFailure& e) {
        const std::string what = e.what();
        if (what.rfind(prefix(face_id), 0) == 0) throw;
        throw geom::NumericalFailure(prefix(face_id) + what);
    } catch (const geom::InvalidInput& e) {
        const std::string what = e.what();
        if (what.rfind(prefix(face_id), 0) == 0) throw;
        throw geom::InvalidInput(prefix(face_id) + what);
    }
}

}  // namespace trimkit::tess
