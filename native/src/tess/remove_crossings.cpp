#include "tess/remove_crossings.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mesh/triangulate_polygon.h"
#include "tess/cell_area_loss.h"
#include "tess/flattened_cell.h"
#include "tess/triangle_bound.h"

namespace trimkit::tess {
namespace {

// A new triangle thinner than this (twice its (u,v) area over its longest side
// squared) is refused: its 3D normal would rest on rounding.
constexpr double kMinShape = 1e-9;

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

bool well_shaped(const std::vector<Eigen::Vector2d>& uv, const std::array<int, 3>& t) {
    const Eigen::Vector2d &a = uv[t[0]], &b = uv[t[1]], &c = uv[t[2]];
    const double longest =
        std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    return cross(b - a, c - a) > kMinShape * longest;
}

class CrossingRemover {
public:
    CrossingRemover(const geom::NurbsSurface& S, TriangleBound& bound, CrossingMesh& mesh, double interior,
                    double total)
        : S_(S), bound_(bound), mesh_(mesh), interior_(interior), total_(total),
          offset_(mesh.uv.size(), -1.0), triangles_of_(mesh.uv.size()), edges_of_(mesh.uv.size()) {
        for (size_t t = 0; t < mesh.triangles.size(); ++t)
            for (int v : mesh.triangles[t]) triangles_of_[v].push_back(static_cast<int>(t));
        for (size_t e = 0; e < mesh.trim_edges.size(); ++e)
            for (int v : mesh.trim_edges[e]) edges_of_[v].push_back(static_cast<int>(e));
    }

    bool remove(int c) {
        if (edges_of_[c].size() != 2) return false;
        const int in = mesh_.trim_edges[edges_of_[c][0]][1] == c ? edges_of_[c][0] : edges_of_[c][1];
        const int out = in == edges_of_[c][0] ? edges_of_[c][1] : edges_of_[c][0];
        if (mesh_.trim_edges[in][1] != c || mesh_.trim_edges[out][0] != c) return false;
        const int a = mesh_.trim_edges[in][0], b = mesh_.trim_edges[out][1];
        if (a == b) return false;
        std::vector<int> ring;
        if (!fan_ring(c, a, b, ring)) return false;
        const std::vector<std::array<int, 3>> best = least_losing(candidates(ring));
        if (best.empty()) return false;
        replace(c, best);
        mesh_.trim_edges[in] = {a, b};
        mesh_.trim_edges[out] = {-1, -1};
        std::replace(edges_of_[b].begin(), edges_of_[b].end(), out, in);
        edges_of_[c].clear();
        return true;
    }

    void compact() {
        std::vector<std::array<int, 3>> triangles;
        for (const auto& t : mesh_.triangles)
            if (t[0] >= 0) triangles.push_back(t);
        mesh_.triangles = std::move(triangles);
        std::vector<std::array<int, 2>> edges;
        for (const auto& e : mesh_.trim_edges)
            if (e[0] >= 0) edges.push_back(e);
        mesh_.trim_edges = std::move(edges);
    }

private:
    // The vertices around c from b to a, counter-clockwise (the triangles' own order),
    // when c's triangles form one fan between its two trim edges.
    bool fan_ring(int c, int a, int b, std::vector<int>& ring) const {
        const std::vector<int>& around = triangles_of_[c];
        ring.assign(1, b);
        for (size_t step = 0; step < around.size(); ++step) {
            int next = -1;
            for (int t : around) {
                const auto& tri = mesh_.triangles[t];
                const int k = static_cast<int>(std::find(tri.begin(), tri.end(), c) - tri.begin());
                if (tri[(k + 1) % 3] == ring.back()) next = tri[(k + 2) % 3];
            }
            if (next < 0 || next == c) return false;
            ring.push_back(next);
            if (next == a) {
                std::vector<int> sorted = ring;
                std::sort(sorted.begin(), sorted.end());
                return step + 1 == around.size() && std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
            }
        }
        return false;
    }

    // Triangulations of the ring without c: ear clipping, then the fans from its ends
    // (the collapses of c onto a or onto b).
    std::vector<std::vector<std::array<int, 3>>> candidates(const std::vector<int>& ring) const {
        std::vector<std::vector<std::array<int, 3>>> out;
        out.push_back(mesh::triangulate_polygon(mesh_.uv, ring));
        const int n = static_cast<int>(ring.size());
        std::vector<std::array<int, 3>> from_a, from_b;
        for (int k = 0; k + 2 < n; ++k) {
            from_b.push_back({ring[0], ring[k + 1], ring[k + 2]});
            from_a.push_back({ring[n - 1], ring[k], ring[k + 1]});
        }
        for (auto* fan : {&from_a, &from_b})
            if (std::none_of(out.begin(), out.end(), [&](const auto& c) { return same_triangles(c, *fan); }))
                out.push_back(std::move(*fan));
        return out;
    }

    // The same triangles, each possibly rotated, in any order (a ring of three
    // vertices gives one triangle three times).
    static bool same_triangles(std::vector<std::array<int, 3>> a, std::vector<std::array<int, 3>> b) {
        auto canonical = [](std::vector<std::array<int, 3>>& ts) {
            for (auto& t : ts) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
            std::sort(ts.begin(), ts.end());
        };
        canonical(a);
        canonical(b);
        return a == b;
    }

    // Of the triangulations within the bound, the one that loses least area
    // (cell_area_loss.h): the area budget pays for what a removal loses. Empty if none is.
    // The loss is the cheaper test, so a candidate losing no less than the best so far
    // is never bounded.
    std::vector<std::array<int, 3>> least_losing(std::vector<std::vector<std::array<int, 3>>> candidates) {
        double least = std::numeric_limits<double>::infinity();
        std::vector<std::array<int, 3>> best;
        for (auto& candidate : candidates) {
            const double loss = area_loss(candidate);
            if (!(loss < least) || !acceptable(candidate)) continue;
            least = loss, best = std::move(candidate);
        }
        return best;
    }

    double area_loss(const std::vector<std::array<int, 3>>& triangles) {
        double loss = 0.0;
        for (const auto& t : triangles)
            loss += triangle_area_loss(evaluator_, {mesh_.uv[t[0]], mesh_.uv[t[1]], mesh_.uv[t[2]]},
                                       {mesh_.xyz[t[0]], mesh_.xyz[t[1]], mesh_.xyz[t[2]]});
        return loss;
    }

    double offset(int v) {
        if (offset_[v] < 0.0) {
            const Eigen::Vector2d& p = mesh_.uv[v];
            offset_[v] = (mesh_.xyz[v] - S_.evaluate(p.x(), p.y())).norm();
        }
        return offset_[v];
    }

    bool acceptable(const std::vector<std::array<int, 3>>& triangles) {
        if (triangles.empty()) return false;
        for (const auto& t : triangles)
            if (!well_shaped(mesh_.uv, t)) return false;
        for (const auto& t : triangles) {
            Eigen::AlignedBox2d box(mesh_.uv[t[0]]);
            const double bound = bound_(box.extend(mesh_.uv[t[1]]).extend(mesh_.uv[t[2]]));
            if (!(bound <= interior_)) return false;
            const double off = std::max({offset(t[0]), offset(t[1]), offset(t[2])});
            if (!(bound + off <= total_)) return false;
        }
        return !has_backward_triangle(S_, mesh_.uv, mesh_.xyz, triangles);
    }

    void replace(int c, const std::vector<std::array<int, 3>>& triangles) {
        for (int t : triangles_of_[c]) {
            for (int v : mesh_.triangles[t]) {
                if (v == c) continue;
                auto& list = triangles_of_[v];
                list.erase(std::remove(list.begin(), list.end(), t), list.end());
            }
            mesh_.triangles[t] = {-1, -1, -1};
        }
        triangles_of_[c].clear();
        for (const auto& t : triangles) {
            const int id = static_cast<int>(mesh_.triangles.size());
            mesh_.triangles.push_back(t);
            for (int v : t) triangles_of_[v].push_back(id);
        }
    }

    const geom::NurbsSurface& S_;
    TriangleBound& bound_;
    SurfaceEvaluator evaluator_{S_};
    CrossingMesh& mesh_;
    double interior_, total_;
    std::vector<double> offset_;  // per vertex, -1 until computed
    std::vector<std::vector<int>> triangles_of_, edges_of_;
};

}  // namespace

int remove_crossings(const geom::NurbsSurface& S, const RevolutionShape* shape, ErrorMode mode, CrossingMesh& mesh,
                     double interior_tolerance, double total_tolerance, mesh::Deadline* deadline) {
    TriangleBound bound(S, shape, mode, interior_tolerance);
    CrossingRemover remover(S, bound, mesh, interior_tolerance, total_tolerance);
    int removed = 0;
    for (size_t v = 0; v < mesh.uv.size(); ++v) {
        if (!mesh.crossing[v]) continue;
        mesh::check_deadline(deadline, "removing crossings");
        if (remover.remove(static_cast<int>(v))) ++removed;
    }
    remover.compact();
    return removed;
}

}  // namespace trimkit::tess
