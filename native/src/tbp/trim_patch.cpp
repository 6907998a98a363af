#include "tbp/trim_patch.h"

#include <chrono>
#include <map>
#include <unordered_map>

#include "mesh/open_edges.h"
#include "mesh/weld_vertices.h"
#include "tbp/domain_arrangement.h"
#include "tbp/polygonize.h"

namespace trimkit::tbp {
namespace {

enum class NodeState { kKept, kDeleted, kTrimmed };

// Parameters within this of 0 lie on the patch's original boundary.
constexpr double kOnDomainSide = 1e-12;

struct Trimmer {
    const TbpHierarchy& target;
    const std::vector<TbpHierarchy>& tool;
    Keep keep;
    TrimStats& stats;
    // cut segments per leaf, in the leaf's local coordinates
    std::unordered_map<int, std::vector<std::array<Eigen::Vector2d, 2>>> cuts;
    std::vector<std::vector<char>> has_cut;  // per level, per node: a cut leaf below
    // kept triangles as root-domain parameters
    std::vector<std::array<Eigen::Vector3d, 3>> kept;
    std::vector<SubTbp> untrimmed;

    bool removed(Containment c) const {
        return keep == Keep::kOutside ? c == Containment::kInside : c == Containment::kOutside;
    }

    // Local (alpha, beta) of root parameter `t` in node n (least squares: t lies in n's plane).
    static Eigen::Vector2d local_of(const TbpNode& n, const Eigen::Vector3d& t) {
        Eigen::Matrix<double, 3, 2> M;
        M.col(0) = n.domain[0] - n.domain[2];
        M.col(1) = n.domain[1] - n.domain[2];
        return (M.transpose() * M).ldlt().solve(M.transpose() * (t - n.domain[2]));
    }

    void emit_leaf(const TbpNode& n) { kept.push_back(n.domain); }

    void delete_branch(int l, int k) {
        // DELETE_SUBPATCH_BRANCH: count the leaves below for the statistics.
        long long leaves = 1;
        for (int d = l; d < target.levels(); ++d) leaves *= target.children_per_node();
        stats.deleted_leaves += static_cast<int>(leaves);
        (void)k;
    }
    void keep_branch(int l, int k) {
        const TbpNode& n = target.node(l, k);
        untrimmed.push_back({l, k, n.domain, n.patch});
        collect_leaves(l, k);
    }
    void collect_leaves(int l, int k) {
        if (l == target.levels()) {
            ++stats.kept_leaves;
            return emit_leaf(target.node(l, k));
        }
        for (int c = 0; c < target.children_per_node(); ++c) collect_leaves(l + 1, target.first_child(k) + c);
    }

    NodeState cut_leaf(int k) {
        const TbpNode& n = target.node(target.levels(), k);
        const TriangleArrangement a = arrange_triangle(cuts[k]);
        ++stats.cut_leaves;
        int deleted = 0;
        for (const ArrangementFace& f : a.faces) {
            ++stats.pieces;
            // classify a point inside the piece on the leaf's base triangle (the
            // surface the cuts were computed on)
            const Eigen::Vector3d l = local_barycentric(f.sample);
            const Eigen::Vector3d x = l[0] * n.base(0) + l[1] * n.base(1) + l[2] * n.base(2);
            if (removed(point_in_solid(tool, x, &stats.inclusion))) {
                ++deleted;
                continue;
            }
            for (const auto& t : f.triangles)
                kept.push_back({n.root_parameter(local_barycentric(a.points[t[0]])),
                                n.root_parameter(local_barycentric(a.points[t[1]])),
                                n.root_parameter(local_barycentric(a.points[t[2]]))});
        }
        if (deleted == static_cast<int>(a.faces.size())) return NodeState::kDeleted;
        return NodeState::kTrimmed;  // cut: not an untrimmed sub-TBP even if all pieces stay
    }

    // [Garcia] Algorithm 5.1, TRIM(p, obj, max_level); kept whole nodes are
    // emitted by the caller (so the topmost ones become sub-TBPs). Re-derived:
    // the extraction's second "then { if inclusion_value != OUTSIDE" is the
    // else branch (partly inside: recurse); "to be deleted" means on the removed
    // side, which is inside for keep = outside and outside for keep = inside.
    // Departure: a node with a cut leaf below skips the box test (its box
    // necessarily meets the solid) and recurses at once.
    NodeState trim(int l, int k) {
        const TbpNode& n = target.node(l, k);
        if (l == target.levels()) {
            if (has_cut[l][k]) return cut_leaf(k);
            const Eigen::Vector3d barycenter = (n.base(0) + n.base(1) + n.base(2)) / 3;
            return removed(point_in_solid(tool, barycenter, &stats.inclusion)) ? NodeState::kDeleted : NodeState::kKept;
        }
        if (!has_cut[l][k]) {
            const Containment inclusion = box_in_solid(tool, n.box, &stats.inclusion);
            if (removed(inclusion)) return NodeState::kDeleted;
            if (inclusion != Containment::kBoundary) return NodeState::kKept;
        }
        std::vector<NodeState> child(target.children_per_node());
        bool all_kept = true, all_deleted = true;
        for (int c = 0; c < target.children_per_node(); ++c) {
            child[c] = trim(l + 1, target.first_child(k) + c);
            all_kept &= child[c] == NodeState::kKept;
            all_deleted &= child[c] == NodeState::kDeleted;
        }
        if (all_kept) return NodeState::kKept;
        if (all_deleted) return NodeState::kDeleted;
        for (int c = 0; c < target.children_per_node(); ++c) {
            if (child[c] == NodeState::kKept) keep_branch(l + 1, target.first_child(k) + c);
            if (child[c] == NodeState::kDeleted) delete_branch(l + 1, target.first_child(k) + c);
        }
        return NodeState::kTrimmed;
    }
};

std::vector<TrimBoundary> boundary_loops(const mesh::Mesh& m, const TbpPatch& patch) {
    const mesh::OpenEdges open = mesh::open_edges(m);
    std::multimap<int, int> next;  // start -> end
    for (const auto& e : open.boundary) next.emplace(e[0], e[1]);
    std::vector<TrimBoundary> out;
    auto uvw = [&](int v) { return Eigen::Vector3d(m.uvs[v].x(), m.uvs[v].y(), 1 - m.uvs[v].x() - m.uvs[v].y()); };
    auto on_side = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
        for (int c = 0; c < 3; ++c)
            if (std::abs(a[c]) <= kOnDomainSide && std::abs(b[c]) <= kOnDomainSide) return true;
        return false;
    };
    while (!next.empty()) {
        TrimBoundary loop;
        const int start = next.begin()->first;
        int v = start;
        while (true) {
            auto it = next.find(v);
            if (it == next.end()) break;  // open chain (non-manifold input); stop here
            const int w = it->second;
            next.erase(it);
            loop.uvw.push_back(uvw(v));
            loop.points.push_back(m.positions[v]);
            loop.on_cut.push_back(on_side(uvw(v), uvw(w)) ? 0 : 1);
            v = w;
            if (v == start) break;
        }
        (void)patch;
        out.push_back(std::move(loop));
    }
    return out;
}

}  // namespace

TrimResult trim_patch(const TbpHierarchy& target, const std::vector<TbpHierarchy>& tool, Keep keep, int face_id) {
    const auto start = std::chrono::steady_clock::now();
    TrimResult result;
    Trimmer t{target, tool, keep, result.stats, {}, {}, {}, {}};

    // a) intersection with every patch of the solid
    Eigen::AlignedBox3d all = target.node(0, 0).box;
    for (const TbpHierarchy& h : tool) all.extend(h.node(0, 0).box);
    const double link = kLinkRelativeTolerance * all.diagonal().norm();
    for (const TbpHierarchy& h : tool) {
        PatchIntersection pi;
        intersect_leaves(target, h, true, pi.segments, result.stats.intersection);
        for (const IntersectionSegment& s : pi.segments) {
            const TbpNode& n = target.node(target.levels(), s.leaf_a);
            t.cuts[s.leaf_a].push_back({Trimmer::local_of(n, s.ends[0].uvw_a), Trimmer::local_of(n, s.ends[1].uvw_a)});
        }
        build_components(pi, link);
        for (auto& c : pi.components) result.curves.push_back(std::move(c));
    }
    // b, c) cut leaves, and which inner nodes have a cut leaf below
    t.has_cut.resize(target.levels() + 1);
    for (int l = 0; l <= target.levels(); ++l) t.has_cut[l].assign(target.level(l).size(), 0);
    for (const auto& [leaf, segs] : t.cuts) {
        int k = leaf;
        for (int l = target.levels(); l >= 0; --l, k = l >= 0 ? target.parent(k) : k) t.has_cut[l][k] = 1;
    }
    // d) TRIM through the hierarchy
    const NodeState root = t.trim(0, 0);
    if (root == NodeState::kKept) t.keep_branch(0, 0);
    if (root == NodeState::kDeleted) t.delete_branch(0, 0);
    result.untrimmed = std::move(t.untrimmed);

    // mesh of the kept region on the exact patch
    const TbpPatch& patch = target.patch();
    mesh::Mesh& m = result.mesh;
    for (const auto& tri : t.kept) {
        const int base = static_cast<int>(m.positions.size());
        for (const Eigen::Vector3d& uvw : tri) {
            m.positions.push_back(patch.evaluate(uvw));
            m.normals.push_back(patch.normal(uvw));
            m.uvs.emplace_back(uvw[0], uvw[1]);
        }
        m.triangles.push_back({base, base + 1, base + 2});
        m.face_ids.push_back(face_id);
    }
    if (!m.positions.empty()) {
        mesh::WeldOptions weld;
        weld.tolerance = kWeldRelativeTolerance * patch.bounding_box().diagonal().norm();
        mesh::weld_vertices(m, weld);
    }
    // e, f) boundary of the kept region
    result.boundaries = boundary_loops(m, patch);
    for (const TrimBoundary& b : result.boundaries)
        for (char c : b.on_cut) result.stats.boundary_segments += c;
    result.stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

TrimResult trim_patch(const TbpPatch& target, const TbpSolid& tool, const TrimOptions& options) {
    const TbpHierarchy h(target, options.levels, options.lod);
    return trim_patch(h, build_hierarchies(tool, options.levels, options.lod), options.keep);
}

mesh::Mesh trim_solid(const TbpSolid& target, const TbpSolid& tool, const TrimOptions& options,
                      std::vector<TrimResult>* parts) {
    validate(target);
    const std::vector<TbpHierarchy> tool_h = build_hierarchies(tool, options.levels, options.lod);
    mesh::Mesh out;
    Eigen::AlignedBox3d box;
    for (std::size_t p = 0; p < target.patches.size(); ++p) {
        const TbpHierarchy h(target.patches[p], options.levels, options.lod);
        TrimResult r = trim_patch(h, tool_h, options.keep, static_cast<int>(p));
        if (r.mesh.vertex_count() > 0) mesh::append(out, r.mesh);
        box.extend(target.patches[p].bounding_box());
        if (parts) parts->push_back(std::move(r));
    }
    if (!out.positions.empty()) {
        mesh::WeldOptions weld;
        weld.tolerance = kWeldRelativeTolerance * box.diagonal().norm();
        mesh::weld_vertices(out, weld);
    }
    return out;
}

}  // namespace trimkit::tbp
