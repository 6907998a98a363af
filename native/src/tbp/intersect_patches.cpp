#include "tbp/intersect_patches.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <unordered_map>

#include "mesh/grid_cell.h"
#include "tbp/triangle_intersection.h"

namespace trimkit::tbp {
namespace {

Triangle3 base_triangle(const TbpNode& n) { return {n.base(0), n.base(1), n.base(2)}; }

bool boxes_meet(const Eigen::AlignedBox3d& a, const Eigen::AlignedBox3d& b, double pad) {
    return (a.min().array() <= b.max().array() + pad).all() && (b.min().array() <= a.max().array() + pad).all();
}

struct Walker {
    const TbpHierarchy& a;
    const TbpHierarchy& b;
    double pad;
    std::vector<IntersectionSegment>& out;
    IntersectionStats& stats;

    void leaf_pair(int ka, int kb) {
        const TbpNode& na = a.node(a.levels(), ka);
        const TbpNode& nb = b.node(b.levels(), kb);
        ++stats.triangle_tests;
        const Triangle3 ta = base_triangle(na), tb = base_triangle(nb);
        Eigen::Vector3d p, q;
        if (!triangle_intersection(ta, tb, p, q)) return;
        ++stats.segments;
        IntersectionSegment s;
        s.leaf_a = ka;
        s.leaf_b = kb;
        const Eigen::Vector3d ends[2] = {p, q};
        for (int e = 0; e < 2; ++e) {
            s.ends[e].position = ends[e];
            s.ends[e].uvw_a = na.root_parameter(barycentric(ta, ends[e]));
            s.ends[e].uvw_b = nb.root_parameter(barycentric(tb, ends[e]));
        }
        out.push_back(s);
    }

    // [Garcia] Algorithm 4.1, TBP_INT(P1, P2, max_level). Re-derived: the
    // extracted conditions "(P1.level, P2.level = max_level)" / "!= max_level"
    // read as "both at max_level" / "neither at max_level"; the leaves of each
    // tree are its own max_level, so trees of different depth work too.
    void tbp_int(int la, int ka, int lb, int kb) {
        const TbpNode& na = a.node(la, ka);
        const TbpNode& nb = b.node(lb, kb);
        ++stats.box_tests;
        if (!boxes_meet(na.box, nb.box, pad)) return;  // no intersection
        const bool a_leaf = la == a.levels(), b_leaf = lb == b.levels();
        if (a_leaf && b_leaf) return leaf_pair(ka, kb);
        // Neither at max_level: split the TBP with the biggest box.
        bool split_a = !a_leaf;
        if (!a_leaf && !b_leaf) split_a = na.box.diagonal().squaredNorm() >= nb.box.diagonal().squaredNorm();
        if (split_a) {
            for (int c = 0; c < a.children_per_node(); ++c) tbp_int(la + 1, a.first_child(ka) + c, lb, kb);
        } else {
            for (int c = 0; c < b.children_per_node(); ++c) tbp_int(la, ka, lb + 1, b.first_child(kb) + c);
        }
    }
};

// Welds points within `tol` with a hash grid (27 neighbouring cells).
class PointWelder {
public:
    explicit PointWelder(double tol) : tol_(tol), cell_(std::max(tol, 1e-300) * 2) {}
    int insert(const Eigen::Vector3d& p) {
        const mesh::GridCell key = mesh::GridCell::of(p, cell_);
        for (int dx = -1; dx <= 1; ++dx)
            for (int dy = -1; dy <= 1; ++dy)
                for (int dz = -1; dz <= 1; ++dz) {
                    auto it = grid_.find({key.x + dx, key.y + dy, key.z + dz});
                    if (it == grid_.end()) continue;
                    for (int id : it->second)
                        if ((points_[id] - p).norm() <= tol_) return id;
                }
        points_.push_back(p);
        grid_[key].push_back(static_cast<int>(points_.size()) - 1);
        return static_cast<int>(points_.size()) - 1;
    }

private:
    double tol_, cell_;
    std::vector<Eigen::Vector3d> points_;
    std::unordered_map<mesh::GridCell, std::vector<int>, mesh::GridCellHash> grid_;
};

}  // namespace

void intersect_leaves(const TbpHierarchy& a, const TbpHierarchy& b, bool use_hierarchy,
                      std::vector<IntersectionSegment>& out, IntersectionStats& stats) {
    Eigen::AlignedBox3d both = a.node(0, 0).box;
    both.extend(b.node(0, 0).box);
    // Boxes are padded by the link tolerance so rounding cannot separate touching boxes.
    Walker w{a, b, kLinkRelativeTolerance * both.diagonal().norm(), out, stats};
    if (use_hierarchy) return w.tbp_int(0, 0, 0, 0);
    for (std::size_t ka = 0; ka < a.leaves().size(); ++ka)
        for (std::size_t kb = 0; kb < b.leaves().size(); ++kb) w.leaf_pair(static_cast<int>(ka), static_cast<int>(kb));
}

void build_components(PatchIntersection& result, double tolerance) {
    // ADD_SEGMENTS: weld ends, drop zero-length and duplicate segments.
    PointWelder welder(tolerance);
    std::vector<IntersectionPoint> vertex;  // first point seen for each welded id
    std::vector<std::array<int, 2>> edges;
    std::vector<IntersectionSegment> kept;
    std::map<std::pair<int, int>, int> seen;
    for (const IntersectionSegment& s : result.segments) {
        int id[2];
        for (int e = 0; e < 2; ++e) {
            id[e] = welder.insert(s.ends[e].position);
            if (id[e] == static_cast<int>(vertex.size())) vertex.push_back(s.ends[e]);
        }
        if (id[0] == id[1]) continue;
        if (!seen.emplace(std::minmax(id[0], id[1]), static_cast<int>(edges.size())).second) continue;
        edges.push_back({id[0], id[1]});
        kept.push_back(s);
    }
    result.segments = std::move(kept);

    // BUILD_COMPONENTS on the graph.
    const int nv = static_cast<int>(vertex.size());
    std::vector<std::vector<int>> incident(nv);
    for (std::size_t e = 0; e < edges.size(); ++e) {
        incident[edges[e][0]].push_back(static_cast<int>(e));
        incident[edges[e][1]].push_back(static_cast<int>(e));
    }
    std::vector<char> used(edges.size(), 0);
    auto other = [&](int e, int v) { return edges[e][0] == v ? edges[e][1] : edges[e][0]; };
    // Walk from v along edge e until a vertex of degree != 2 (or back at `v`).
    auto walk = [&](int v, int e, IntersectionComponent& c) {
        const int start = v;
        c.points.push_back(vertex[v]);
        while (true) {
            used[e] = 1;
            v = other(e, v);
            if (v == start) {
                c.closed = true;
                return;
            }
            c.points.push_back(vertex[v]);
            if (incident[v].size() != 2) return;
            e = incident[v][0] == e ? incident[v][1] : incident[v][0];
        }
    };
    for (int v = 0; v < nv; ++v) {
        if (incident[v].size() >= 3) result.junctions.push_back(vertex[v].position);
        if (incident[v].size() == 2) continue;
        for (int e : incident[v])
            if (!used[e]) {
                IntersectionComponent c;
                walk(v, e, c);
                result.components.push_back(std::move(c));
            }
    }
    for (std::size_t e = 0; e < edges.size(); ++e)  // remaining: cycles of degree-2 vertices
        if (!used[e]) {
            IntersectionComponent c;
            walk(edges[e][0], static_cast<int>(e), c);
            result.components.push_back(std::move(c));
        }
}

PatchIntersection intersect_patches(const TbpHierarchy& a, const TbpHierarchy& b, bool use_hierarchy) {
    PatchIntersection result;
    intersect_leaves(a, b, use_hierarchy, result.segments, result.stats);
    Eigen::AlignedBox3d both = a.node(0, 0).box;
    both.extend(b.node(0, 0).box);
    build_components(result, kLinkRelativeTolerance * both.diagonal().norm());
    return result;
}

PatchIntersection intersect_solids(const std::vector<TbpHierarchy>& a, const std::vector<TbpHierarchy>& b,
                                   bool use_hierarchy) {
    PatchIntersection all;
    for (const TbpHierarchy& ha : a)
        for (const TbpHierarchy& hb : b) intersect_leaves(ha, hb, use_hierarchy, all.segments, all.stats);
    Eigen::AlignedBox3d box;
    for (const TbpHierarchy& h : a) box.extend(h.node(0, 0).box);
    for (const TbpHierarchy& h : b) box.extend(h.node(0, 0).box);
    if (!box.isEmpty()) build_components(all, kLinkRelativeTolerance * box.diagonal().norm());
    return all;
}

}  // namespace trimkit::tbp
