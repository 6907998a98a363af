#include "tess/snap_boundary_vertices.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <tuple>
#include <unordered_map>

#include <Eigen/Geometry>

#include "mesh/grid_cell.h"
#include "mesh/parallel_sort.h"
#include "tess/unpaired_sides.h"

namespace trimkit::tess {

using mesh::GridCell;
using mesh::GridCellHash;
namespace {

bool position_less(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return std::tie(a.x(), a.y(), a.z()) < std::tie(b.x(), b.y(), b.z());
}

// Vertices sorted by key, ties by index; equal keys form one group. The keys are
// sorted with their indices beside them (one contiguous array, not an index array
// that looks its keys up): the model mesh has 10^5-10^6 vertices and the joining
// stages group them several times.
template <typename Key>
std::vector<std::int32_t> groups_by_key(const std::vector<Key>& key, int threads) {
    const auto n = static_cast<std::int32_t>(key.size());
    std::vector<std::pair<Key, std::int32_t>> sorted(n);
    for (std::int32_t i = 0; i < n; ++i) sorted[i] = {key[i], i};
    mesh::parallel_sort(sorted.begin(), sorted.end(), threads);
    std::vector<std::int32_t> group(n);
    for (std::int32_t k = 0; k < n; ++k)
        group[sorted[k].second] =
            k > 0 && sorted[k].first == sorted[k - 1].first ? group[sorted[k - 1].second] : sorted[k].second;
    return group;
}

}  // namespace

std::vector<std::int32_t> position_groups(const mesh::Mesh& mesh, bool as_float, int threads) {
    // Float keys are kept as floats, never rounded back to double: GCC 12 at -O2/-O3
    // left x and y of some vertices unrounded in p.cast<float>().cast<double>() (and
    // in the scalar double(float(x)) spelling), so two vertices written at one float
    // position fell into different groups (occ22470 reported 6 open edges on a mesh
    // whose written file has none).
    const std::size_t n = mesh.positions.size();
    if (as_float) {
        std::vector<std::array<float, 3>> key(n);
        for (std::size_t i = 0; i < n; ++i)
            key[i] = {static_cast<float>(mesh.positions[i].x()), static_cast<float>(mesh.positions[i].y()),
                      static_cast<float>(mesh.positions[i].z())};
        return groups_by_key(key, threads);
    }
    std::vector<std::array<double, 3>> key(n);
    for (std::size_t i = 0; i < n; ++i)
        key[i] = {mesh.positions[i].x(), mesh.positions[i].y(), mesh.positions[i].z()};
    return groups_by_key(key, threads);
}

std::vector<std::array<std::int32_t, 3>> position_triangles(const mesh::Mesh& mesh,
                                                            const std::vector<std::int32_t>& group) {
    std::vector<std::array<std::int32_t, 3>> out(mesh.triangles.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) out[t][k] = group[mesh.triangles[t][k]];
    return out;
}

std::size_t count_position_open_edges(const mesh::Mesh& mesh, int threads) {
    mesh::Mesh topology;
    topology.positions = mesh.positions;
    topology.triangles = position_triangles(mesh, position_groups(mesh, true, threads));
    return unpaired_sides(mesh, topology.triangles, threads).size();
}

std::size_t snap_boundary_vertices(mesh::Mesh& mesh, double tolerance, bool* degenerate, int threads) {
    if (degenerate) *degenerate = false;
    if (!(tolerance > 0.0) || mesh.positions.empty()) return 0;
    const std::vector<std::int32_t> group = position_groups(mesh, false, threads);
    mesh::Mesh topology;
    topology.positions = mesh.positions;
    topology.triangles = position_triangles(mesh, group);
    std::vector<std::int32_t> ends;  // position groups on open edges
    for (const TriangleSide& s : unpaired_sides(mesh, topology.triangles, threads)) {
        ends.push_back(topology.triangles[s.triangle][s.corner]);
        ends.push_back(topology.triangles[s.triangle][(s.corner + 1) % 3]);
    }
    std::sort(ends.begin(), ends.end());
    ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
    if (ends.size() < 2) return 0;

    // Candidate pairs within the tolerance, closest first (ties by position).
    const double cell = tolerance;
    auto key = [&](const Eigen::Vector3d& p) { return GridCell::of(p, cell); };
    std::unordered_map<GridCell, std::vector<std::int32_t>, GridCellHash> grid;
    for (std::int32_t g : ends) grid[key(mesh.positions[g])].push_back(g);
    struct Pair {
        double d;
        std::int32_t a, b;
    };
    std::vector<Pair> pairs;
    const std::size_t max_pairs = kMaxSnapPairsPerEnd * ends.size();
    for (std::int32_t g : ends) {
        if (pairs.size() > max_pairs) {
            if (degenerate) *degenerate = true;
            return 0;
        }
        const GridCell k = key(mesh.positions[g]);
        for (long long dx = -1; dx <= 1; ++dx)
            for (long long dy = -1; dy <= 1; ++dy)
                for (long long dz = -1; dz <= 1; ++dz) {
                    const auto it = grid.find({k.x + dx, k.y + dy, k.z + dz});
                    if (it == grid.end()) continue;
                    for (std::int32_t h : it->second) {
                        if (!position_less(mesh.positions[g], mesh.positions[h])) continue;
                        const double d = (mesh.positions[g] - mesh.positions[h]).norm();
                        if (d <= tolerance) pairs.push_back({d, g, h});
                    }
                }
    }
    std::sort(pairs.begin(), pairs.end(), [&](const Pair& x, const Pair& y) {
        if (x.d != y.d) return x.d < y.d;
        if (mesh.positions[x.a] != mesh.positions[y.a]) return position_less(mesh.positions[x.a], mesh.positions[y.a]);
        return position_less(mesh.positions[x.b], mesh.positions[y.b]);
    });

    if (pairs.empty()) return 0;
    // Only groups in some pair can join: the maps below are built for them.
    std::vector<std::int32_t> involved;
    for (const Pair& p : pairs) involved.push_back(p.a), involved.push_back(p.b);
    std::sort(involved.begin(), involved.end());
    involved.erase(std::unique(involved.begin(), involved.end()), involved.end());

    // Groups sharing a triangle may never meet; nor may two vertices of one face
    // (a face's own boundary is closed by its triangulation, and folding it onto
    // itself would fold triangles).
    std::map<std::int32_t, std::set<std::int32_t>> neighbours, faces;
    // Exception: a closed surface's seam. One face's two vertices on either side of
    // its seam lie at (nearly) one position with uvs far apart (a period); they are
    // meant to be one point, and joining them folds nothing. Each end group's uvs per
    // face, and each face's uv extent, tell them apart.
    std::map<std::pair<std::int32_t, std::int32_t>, std::vector<Eigen::Vector2d>> face_uvs;
    std::unordered_map<std::int32_t, Eigen::AlignedBox2d> uv_box;
    {
        std::vector<char> is_end(mesh.positions.size(), 0);
        for (std::int32_t g : involved) is_end[g] = 1;
        const bool with_uvs = mesh.has_face_ids() && mesh.has_uvs();
        for (std::size_t i = 0; i < topology.triangles.size(); ++i) {
            const auto& t = topology.triangles[i];
            for (int a = 0; a < 3; ++a) {
                if (with_uvs) uv_box[mesh.face_ids[i]].extend(mesh.uvs[mesh.triangles[i][a]]);
                if (is_end[t[a]]) {
                    if (mesh.has_face_ids()) faces[t[a]].insert(mesh.face_ids[i]);
                    if (with_uvs) face_uvs[{t[a], mesh.face_ids[i]}].push_back(mesh.uvs[mesh.triangles[i][a]]);
                    for (int b = 0; b < 3; ++b)
                        if (b != a) neighbours[t[a]].insert(t[b]);
                }
            }
        }
    }
    // Members of two clusters may share face f when every pair of their uvs in f lies
    // at least this share of the face's uv extent apart (a seam).
    constexpr double kSeamUvShare = 0.25;
    const auto across_seam = [&](const std::vector<std::int32_t>& xs, const std::vector<std::int32_t>& ys,
                                 std::int32_t f) {
        const auto box = uv_box.find(f);
        if (box == uv_box.end()) return false;
        const double span = kSeamUvShare * box->second.sizes().maxCoeff();
        if (!(span > 0.0)) return false;
        bool any = false;
        for (std::int32_t x : xs) {
            const auto ux = face_uvs.find({x, f});
            if (ux == face_uvs.end()) continue;
            for (std::int32_t y : ys) {
                const auto uy = face_uvs.find({y, f});
                if (uy == face_uvs.end()) continue;
                for (const Eigen::Vector2d& a : ux->second)
                    for (const Eigen::Vector2d& b : uy->second) {
                        if ((a - b).norm() < span) return false;
                        any = true;
                    }
            }
        }
        return any;
    };

    // Union of clusters, each with its members, its representative (smallest
    // position) and the groups its members share triangles with.
    std::unordered_map<std::int32_t, std::int32_t> parent;
    std::unordered_map<std::int32_t, std::vector<std::int32_t>> members;
    std::unordered_map<std::int32_t, std::set<std::int32_t>> blocked, cluster_faces;
    for (std::int32_t g : involved) {
        parent[g] = g;
        members[g] = {g};
        blocked[g] = neighbours[g];
        cluster_faces[g] = faces[g];
    }
    const auto find = [&](std::int32_t g) {
        while (parent[g] != g) g = parent[g] = parent[parent[g]];
        return g;
    };
    for (const Pair& p : pairs) {
        std::int32_t ra = find(p.a), rb = find(p.b);
        if (ra == rb) continue;
        if (position_less(mesh.positions[rb], mesh.positions[ra])) std::swap(ra, rb);  // ra: the smaller
        bool ok = true;
        for (std::int32_t m : members[rb])
            if (blocked[ra].count(m) || (mesh.positions[m] - mesh.positions[ra]).norm() > tolerance) ok = false;
        for (std::int32_t m : members[ra])
            if (blocked[rb].count(m)) ok = false;
        for (std::int32_t f : cluster_faces[rb])
            if (ok && cluster_faces[ra].count(f) && !across_seam(members[ra], members[rb], f)) ok = false;
        if (!ok) continue;
        cluster_faces[ra].insert(cluster_faces[rb].begin(), cluster_faces[rb].end());
        cluster_faces.erase(rb);
        parent[rb] = ra;
        members[ra].insert(members[ra].end(), members[rb].begin(), members[rb].end());
        blocked[ra].insert(blocked[rb].begin(), blocked[rb].end());
        members.erase(rb);
        blocked.erase(rb);
    }

    // Move every vertex of a snapped group onto its cluster's representative.
    std::size_t moved = 0;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const std::int32_t g = group[v];
        const auto it = parent.find(g);
        if (it == parent.end()) continue;
        const std::int32_t r = find(g);
        if (r == g) continue;
        mesh.positions[v] = mesh.positions[r];
        ++moved;
    }
    return moved;
}

}  // namespace trimkit::tess
