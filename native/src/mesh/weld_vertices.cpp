#include "mesh/weld_vertices.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "geom/error.h"
#include "mesh/grid_cell.h"

namespace trimkit::mesh {
namespace {

// The grid's cells are never smaller than this fraction of the largest
// coordinate, so cell indices stay far inside int64 (|index| <= 1e12) even for a
// zero or tiny tolerance; a larger cell only costs time, never a missed pair.
constexpr double kMinRelativeCellSize = 1e-12;

constexpr double kPi = 3.14159265358979323846;

void check_options(const WeldOptions& options) {
    if (!std::isfinite(options.tolerance) || options.tolerance < 0.0)
        throw geom::InvalidInput("weld_vertices: tolerance = " +
                                 geom::format_value(options.tolerance) +
                                 "; expected a finite distance >= 0");
    if (!std::isfinite(options.split_uv_distance) || options.split_uv_distance < 0.0)
        throw geom::InvalidInput("weld_vertices: split_uv_distance = " +
                                 geom::format_value(options.split_uv_distance) +
                                 "; expected a finite distance >= 0");
    if (!std::isfinite(options.split_normal_angle) || options.split_normal_angle < 0.0)
        throw geom::InvalidInput("weld_vertices: split_normal_angle = " +
                                 geom::format_value(options.split_normal_angle) +
                                 "; expected a finite angle >= 0 (radians)");
}

// Lexicographic order of (position, normal, uv, index): the order in which
// vertices are offered as representatives.
bool vertex_less(const Mesh& mesh, std::int32_t a, std::int32_t b) {
    for (int k = 0; k < 3; ++k)
        if (mesh.positions[a][k] != mesh.positions[b][k])
            return mesh.positions[a][k] < mesh.positions[b][k];
    if (mesh.has_normals())
        for (int k = 0; k < 3; ++k)
            if (mesh.normals[a][k] != mesh.normals[b][k]) return mesh.normals[a][k] < mesh.normals[b][k];
    if (mesh.has_uvs())
        for (int k = 0; k < 2; ++k)
            if (mesh.uvs[a][k] != mesh.uvs[b][k]) return mesh.uvs[a][k] < mesh.uvs[b][k];
    return a < b;
}

// The representative vertex of every vertex's cluster (a vertex that
// represents itself is a representative). Assumes a valid mesh and options.
std::vector<std::int32_t> representatives(const Mesh& mesh, const WeldOptions& options) {
    const auto n = static_cast<std::int32_t>(mesh.positions.size());
    double max_abs = 0.0;
    for (const auto& p : mesh.positions) max_abs = std::max(max_abs, p.cwiseAbs().maxCoeff());
    double cell = std::max(options.tolerance, max_abs * kMinRelativeCellSize);
    if (!(cell > 0.0)) cell = 1.0;  // every vertex at the origin, tolerance 0

    std::vector<GridCell> keys(n);
    for (std::int32_t i = 0; i < n; ++i) {
        const Eigen::Vector3d c = (mesh.positions[i] / cell).array().floor();
        keys[i] = {static_cast<std::int64_t>(c.x()), static_cast<std::int64_t>(c.y()),
                   static_cast<std::int64_t>(c.z())};
    }
    // Vertex indices grouped by grid cell: `by_cell` sorted by cell, `cells`
    // maps a cell to its [begin, end) range in `by_cell`.
    std::vector<std::int32_t> by_cell(n);
    std::iota(by_cell.begin(), by_cell.end(), 0);
    std::sort(by_cell.begin(), by_cell.end(), [&](std::int32_t a, std::int32_t b) {
        return std::tie(keys[a].x, keys[a].y, keys[a].z, a) <
               std::tie(keys[b].x, keys[b].y, keys[b].z, b);
    });
    std::unordered_map<GridCell, std::pair<std::int32_t, std::int32_t>, GridCellHash> cells;
    cells.reserve(static_cast<std::size_t>(n));
    for (std::int32_t begin = 0, end = 0; begin < n; begin = end) {
        while (end < n && keys[by_cell[end]] == keys[by_cell[begin]]) ++end;
        cells.emplace(keys[by_cell[begin]], std::make_pair(begin, end));
    }

    std::vector<std::int32_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(),
              [&](std::int32_t a, std::int32_t b) { return vertex_less(mesh, a, b); });

    const double tol2 = options.tolerance * options.tolerance;
    const bool split = options.keep_split_normals && mesh.has_normals();
    const bool split_uvs = options.keep_split_uvs && mesh.has_uvs();
    const double min_cos = std::cos(std::min(options.split_normal_angle, kPi));
    std::vector<std::int32_t> rep(n, -1);
    for (std::int32_t r : order) {
        if (rep[r] != -1) continue;
        rep[r] = r;
        const Eigen::Vector3d& p = mesh.positions[r];
        for (std::int64_t dx = -1; dx <= 1; ++dx)
            for (std::int64_t dy = -1; dy <= 1; ++dy)
                for (std::int64_t dz = -1; dz <= 1; ++dz) {
                    const auto it = cells.find({keys[r].x + dx, keys[r].y + dy, keys[r].z + dz});
                    if (it == cells.end()) continue;
                    for (std::int32_t c = it->second.first; c < it->second.second; ++c) {
                        const std::int32_t j = by_cell[c];
                        if (rep[j] != -1) continue;
                        if ((mesh.positions[j] - p).squaredNorm() > tol2) continue;
                        if (split && mesh.normals[j].dot(mesh.normals[r]) < min_cos) continue;
                        if (split_uvs && (mesh.uvs[j] - mesh.uvs[r]).norm() > options.split_uv_distance) continue;
                        rep[j] = r;
                    }
                }
    }
    return rep;
}

// vertex_map and vertex_count from the representatives: welded vertices
// numbered in order of their cluster's first input vertex.
WeldResult number_clusters(const std::vector<std::int32_t>& rep) {
    WeldResult result;
    result.vertex_map.assign(rep.size(), -1);
    std::vector<std::int32_t> new_index(rep.size(), -1);
    for (std::size_t i = 0; i < rep.size(); ++i) {
        std::int32_t& target = new_index[rep[i]];
        if (target == -1) target = result.vertex_count++;
        result.vertex_map[i] = target;
    }
    return result;
}

}  // namespace

WeldResult weld_map(const Mesh& mesh, const WeldOptions& options) {
    check_options(options);
    validate(mesh);
    return number_clusters(representatives(mesh, options));
}

WeldResult weld_vertices(Mesh& mesh, const WeldOptions& options) {
    check_options(options);
    validate(mesh);
    const std::vector<std::int32_t> rep = representatives(mesh, options);
    WeldResult result = number_clusters(rep);
    const std::vector<std::int32_t>& map = result.vertex_map;

    Mesh out;
    out.positions.resize(result.vertex_count);
    if (mesh.has_normals()) out.normals.resize(result.vertex_count);
    if (mesh.has_uvs()) out.uvs.resize(result.vertex_count);
    for (std::size_t i = 0; i < rep.size(); ++i) {
        if (rep[i] != static_cast<std::int32_t>(i)) continue;
        const std::int32_t k = map[i];
        out.positions[k] = mesh.positions[i];
        if (mesh.has_normals()) out.normals[k] = mesh.normals[i];
        if (mesh.has_uvs()) out.uvs[k] = mesh.uvs[i];
    }

    out.triangles.reserve(mesh.triangles.size());
    out.face_ids.reserve(mesh.face_ids.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& in = mesh.triangles[t];
        const std::array<std::int32_t, 3> tri{map[in[0]], map[in[1]], map[in[2]]};
        if (options.remove_degenerate_triangles &&
            (tri[0] == tri[1] || tri[1] == tri[2] || tri[2] == tri[0])) {
            ++result.removed_triangles;
            continue;
        }
        out.triangles.push_back(tri);
        if (mesh.has_face_ids()) out.face_ids.push_back(mesh.face_ids[t]);
    }

    // Remap edges, drop collapsed ones, merge duplicates by or-ing their flags.
    std::vector<FlaggedEdge> edges;
    edges.reserve(mesh.edges.size());
    for (const auto& e : mesh.edges) {
        const std::int32_t a = map[e.v0], b = map[e.v1];
        if (a != b) edges.push_back({std::min(a, b), std::max(a, b), e.flags});
    }
    std::sort(edges.begin(), edges.end(), [](const FlaggedEdge& x, const FlaggedEdge& y) {
        return std::make_pair(x.v0, x.v1) < std::make_pair(y.v0, y.v1);
    });
    for (const auto& e : edges) {
        if (!out.edges.empty() && out.edges.back().v0 == e.v0 && out.edges.back().v1 == e.v1)
            out.edges.back().flags |= e.flags;
        else
            out.edges.push_back(e);
    }
    out.face_colors = mesh.face_colors;
    mesh = std::move(out);
    return result;
}

}  // namespace trimkit::mesh
