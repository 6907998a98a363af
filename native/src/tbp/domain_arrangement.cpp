#include "tbp/domain_arrangement.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>

#include "mesh/triangulate_polygon.h"

namespace trimkit::tbp {
namespace {

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// Clamp onto the unit triangle (alpha, beta >= 0, alpha + beta <= 1), snapping
// coordinates within kArrangementSnap of a side onto it.
Eigen::Vector2d clamp_to_triangle(Eigen::Vector2d p) {
    if (p.x() < kArrangementSnap) p.x() = 0;
    if (p.y() < kArrangementSnap) p.y() = 0;
    const double s = p.x() + p.y();
    if (s > 1 - kArrangementSnap) {
        const double excess = s - 1;
        p.x() -= excess / 2, p.y() -= excess / 2;
        if (p.x() < 0) p.y() += p.x(), p.x() = 0;
        if (p.y() < 0) p.x() += p.y(), p.y() = 0;
    }
    return p;
}

class Builder {
public:
    std::vector<Eigen::Vector2d> pts;
    std::set<std::pair<int, int>> edges;  // (min, max)

    int vertex(const Eigen::Vector2d& p) {
        for (std::size_t i = 0; i < pts.size(); ++i)
            if ((pts[i] - p).norm() <= kArrangementSnap) return static_cast<int>(i);
        pts.push_back(p);
        return static_cast<int>(pts.size()) - 1;
    }
    void edge(int a, int b) {
        if (a != b) edges.insert(std::minmax(a, b));
    }

    // Splits every edge at crossings with other edges and at vertices lying on it.
    void split_all() {
        for (int pass = 0; pass < 4; ++pass) {
            const std::vector<std::pair<int, int>> list(edges.begin(), edges.end());
            // crossings create vertices
            for (std::size_t i = 0; i < list.size(); ++i)
                for (std::size_t j = i + 1; j < list.size(); ++j) {
                    const auto [a, b] = list[i];
                    const auto [c, d] = list[j];
                    if (a == c || a == d || b == c || b == d) continue;
                    const Eigen::Vector2d r = pts[b] - pts[a], s = pts[d] - pts[c];
                    const double den = cross2(r, s);
                    if (std::abs(den) < 1e-300) continue;
                    const double t = cross2(pts[c] - pts[a], s) / den, u = cross2(pts[c] - pts[a], r) / den;
                    if (t <= 0 || t >= 1 || u <= 0 || u >= 1) continue;
                    vertex(clamp_to_triangle(pts[a] + t * r));
                }
            // vertices on edges split them
            bool changed = false;
            std::set<std::pair<int, int>> next;
            for (const auto& [a, b] : list) {
                const Eigen::Vector2d r = pts[b] - pts[a];
                const double len2 = r.squaredNorm();
                std::vector<std::pair<double, int>> on{{0.0, a}, {1.0, b}};
                for (std::size_t v = 0; v < pts.size(); ++v) {
                    if (static_cast<int>(v) == a || static_cast<int>(v) == b) continue;
                    const double t = (pts[v] - pts[a]).dot(r) / len2;
                    if (t <= 0 || t >= 1) continue;
                    if ((pts[a] + t * r - pts[v]).norm() <= kArrangementSnap) on.emplace_back(t, static_cast<int>(v));
                }
                if (on.size() > 2) changed = true;
                std::sort(on.begin(), on.end());
                for (std::size_t k = 0; k + 1 < on.size(); ++k)
                    if (on[k].second != on[k + 1].second) next.insert(std::minmax(on[k].second, on[k + 1].second));
            }
            edges = std::move(next);
            if (!changed) break;
        }
    }

    std::vector<std::vector<int>> adjacency() const {
        std::vector<std::vector<int>> adj(pts.size());
        for (const auto& [a, b] : edges) adj[a].push_back(b), adj[b].push_back(a);
        return adj;
    }

    // Drops edges ending at a vertex of degree 1, repeatedly (dangling cut ends).
    void prune_dangling() {
        while (true) {
            const auto adj = adjacency();
            bool removed = false;
            for (auto it = edges.begin(); it != edges.end();) {
                if (adj[it->first].size() == 1 || adj[it->second].size() == 1) {
                    it = edges.erase(it);
                    removed = true;
                } else {
                    ++it;
                }
            }
            if (!removed) return;
        }
    }

    // Joins every component that does not reach the triangle's corners to the
    // sides with two horizontal cuts (leftmost vertex towards alpha = 0,
    // rightmost towards alpha + beta = 1), so faces are simply connected.
    bool connect_islands() {
        const auto adj = adjacency();
        std::vector<int> comp(pts.size(), -1);
        int n = 0;
        for (std::size_t s = 0; s < pts.size(); ++s) {
            if (comp[s] >= 0 || adj[s].empty()) continue;
            std::vector<int> stack{static_cast<int>(s)};
            comp[s] = n;
            while (!stack.empty()) {
                const int v = stack.back();
                stack.pop_back();
                for (int w : adj[v])
                    if (comp[w] < 0) comp[w] = n, stack.push_back(w);
            }
            ++n;
        }
        bool added = false;
        for (int c = 0; c < n; ++c) {
            if (c == comp[0]) continue;
            int lo = -1, hi = -1;
            for (std::size_t v = 0; v < pts.size(); ++v) {
                if (comp[v] != c) continue;
                if (lo < 0 || pts[v].x() < pts[lo].x()) lo = static_cast<int>(v);
                if (hi < 0 || pts[v].x() > pts[hi].x()) hi = static_cast<int>(v);
            }
            const Eigen::Vector2d l = pts[lo], h = pts[hi];
            edge(lo, vertex(Eigen::Vector2d(0, l.y())));
            edge(hi, vertex(Eigen::Vector2d(1 - h.y(), h.y())));
            added = true;
        }
        return added;
    }
};

// A vertex where the arrangement goes straight through (two edges, on one line) is a
// corner of no face: left out of the triangulation, in every face that has it, so the
// faces stay conforming (a vertex where three or more edges meet stays, straight or not).
constexpr double kStraightTurn = 1e-12;  // |cross| in local coordinates (legs of length 1)

std::vector<int> without_straight_vertices(const std::vector<Eigen::Vector2d>& pts,
                                           const std::vector<std::vector<int>>& adjacency,
                                           const std::vector<int>& poly) {
    std::vector<int> kept;
    for (int v : poly) {
        const auto& nb = adjacency[v];
        const bool straight = v > 2 && nb.size() == 2 &&
                              std::abs(cross2(pts[v] - pts[nb[0]], pts[nb[1]] - pts[v])) <= kStraightTurn &&
                              (pts[v] - pts[nb[0]]).dot(pts[nb[1]] - pts[v]) > 0.0;
        if (!straight) kept.push_back(v);
    }
    return kept.size() >= 3 ? kept : poly;
}

}  // namespace

TriangleArrangement arrange_triangle(const std::vector<std::array<Eigen::Vector2d, 2>>& cuts) {
    Builder g;
    g.pts = {Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 1), Eigen::Vector2d(0, 0)};
    g.edge(0, 1), g.edge(1, 2), g.edge(2, 0);
    for (const auto& c : cuts) g.edge(g.vertex(clamp_to_triangle(c[0])), g.vertex(clamp_to_triangle(c[1])));
    g.split_all();
    g.prune_dangling();
    if (g.connect_islands()) {
        g.split_all();
        g.prune_dangling();
    }

    // Faces: at each vertex sort neighbours by angle; the face left of a->b
    // continues with b->c, c the neighbour of b just clockwise of a.
    const auto adj0 = g.adjacency();
    std::vector<std::vector<int>> adj = adj0;
    for (std::size_t v = 0; v < adj.size(); ++v)
        std::sort(adj[v].begin(), adj[v].end(), [&](int a, int b) {
            const Eigen::Vector2d da = g.pts[a] - g.pts[v], db = g.pts[b] - g.pts[v];
            return std::atan2(da.y(), da.x()) < std::atan2(db.y(), db.x());
        });
    std::set<std::pair<int, int>> done;
    TriangleArrangement out;
    out.points = g.pts;
    for (std::size_t s = 0; s < adj.size(); ++s)
        for (int t : adj[s]) {
            if (done.count({static_cast<int>(s), t})) continue;
            std::vector<int> poly;
            int a = static_cast<int>(s), b = t;
            while (!done.count({a, b})) {
                done.insert({a, b});
                poly.push_back(a);
                const auto& nb = adj[b];
                const int i = static_cast<int>(std::find(nb.begin(), nb.end(), a) - nb.begin());
                const int c = nb[(i + nb.size() - 1) % nb.size()];
                a = b, b = c;
            }
            double area = 0;
            for (std::size_t k = 0; k < poly.size(); ++k)
                area += cross2(g.pts[poly[k]], g.pts[poly[(k + 1) % poly.size()]]);
            if (area <= 0) continue;  // the outer boundary, traversed clockwise
            ArrangementFace f;
            f.polygon = poly;
            f.triangles = mesh::triangulate_polygon(g.pts, without_straight_vertices(g.pts, adj0, poly));
            double best = -1;
            for (const auto& tri : f.triangles) {
                const double ta = cross2(g.pts[tri[1]] - g.pts[tri[0]], g.pts[tri[2]] - g.pts[tri[0]]);
                if (ta > best) best = ta, f.sample = (g.pts[tri[0]] + g.pts[tri[1]] + g.pts[tri[2]]) / 3;
            }
            if (!f.triangles.empty()) out.faces.push_back(std::move(f));
        }
    return out;
}

}  // namespace trimkit::tbp
