#include "tess/fill_sliver_holes.h"

#include <algorithm>
#include <functional>
#include <map>
#include <queue>

#include "tess/snap_boundary_vertices.h"
#include "tess/unpaired_sides.h"

namespace trimkit::tess {
namespace {

// A hole's cycle runs its open sides the filling way where it can: a side taken
// against that way costs this many times its length.
constexpr double kBackwardCost = 2.0;

// A side of the hole in the direction a filling triangle runs it (against the open
// side of the triangle beside it): from group `from` to group `to`, with the mesh
// vertex at `from` (from that triangle) and the triangle's face.
struct HoleSide {
    std::int32_t from = 0, to = 0;
    std::int32_t vertex = 0, end_vertex = 0;  // mesh vertices at `from` and `to`
    std::int32_t face = 0;
    std::size_t index = 0;  // in the list of open sides
    bool backward = false;  // runs along its open side (a neighbour folded the wrong way)
};

// The hole's width as 2 A / P (A the area of its fan from the first vertex, P its
// perimeter): the inradius of a triangle, half the width of a long thin strip.
double hole_width(const mesh::Mesh& mesh, const std::vector<HoleSide>& cycle) {
    const auto at = [&](std::size_t i) -> const Eigen::Vector3d& { return mesh.positions[cycle[i].vertex]; };
    double area = 0.0, perimeter = 0.0;
    for (std::size_t i = 0; i < cycle.size(); ++i) {
        perimeter += (at((i + 1) % cycle.size()) - at(i)).norm();
        if (i >= 1 && i + 1 < cycle.size()) area += 0.5 * (at(i) - at(0)).cross(at(i + 1) - at(0)).norm();
    }
    return perimeter > 0.0 ? 2.0 * area / perimeter : 0.0;
}

// The shortest cycle (in 3D length) through side `first` and unused sides: Dijkstra
// from its end back to its start, so that at a vertex where two holes touch the
// cycle keeps to the narrow one. Empty if none closes within max_sides sides (or
// after max_sides² visits).
std::vector<HoleSide> shortest_cycle(const mesh::Mesh& mesh, const std::vector<HoleSide>& sides, std::size_t first,
                                     const std::multimap<std::int32_t, std::size_t>& by_start,
                                     const std::vector<char>& used, int max_sides) {
    struct Label {
        double distance;
        int count;
        std::size_t via;  // the side that reached the group
    };
    std::map<std::int32_t, Label> labels;
    using Item = std::pair<double, std::int32_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    const std::int32_t goal = sides[first].from;
    labels[sides[first].to] = {0.0, 1, first};
    queue.push({0.0, sides[first].to});
    int visits = 0;
    while (!queue.empty() && ++visits <= max_sides * max_sides) {
        const auto [d, g] = queue.top();
        queue.pop();
        const Label here = labels.at(g);
        if (d > here.distance) continue;
        if (g == goal) break;
        if (here.count >= max_sides) continue;
        const auto [lo, hi] = by_start.equal_range(g);
        for (auto it = lo; it != hi; ++it) {
            const std::size_t k = it->second;
            if (used[sides[k].index] || sides[k].index == sides[first].index) continue;
            const double length = (mesh.positions[sides[k].vertex] - mesh.positions[sides[k].end_vertex]).norm();
            const double step = sides[k].backward ? kBackwardCost * length : length;
            const auto found = labels.find(sides[k].to);
            if (found != labels.end() && found->second.distance <= d + step) continue;
            labels[sides[k].to] = {d + step, here.count + 1, k};
            queue.push({d + step, sides[k].to});
        }
    }
    const auto reached = labels.find(goal);
    if (reached == labels.end() || goal == sides[first].to) return {};
    std::vector<HoleSide> cycle;
    for (std::int32_t g = goal; g != sides[first].to; g = sides[labels.at(g).via].from) {
        cycle.push_back(sides[labels.at(g).via]);
        if (static_cast<int>(cycle.size()) > max_sides) return {};
    }
    cycle.push_back(sides[first]);
    std::reverse(cycle.begin(), cycle.end());
    return cycle;
}

}  // namespace

int fill_sliver_holes(mesh::Mesh& mesh, double width, int max_sides, int threads) {
    const std::vector<std::int32_t> group = position_groups(mesh, true, threads);
    const auto topology = position_triangles(mesh, group);
    std::vector<HoleSide> sides;
    for (const TriangleSide& side : unpaired_sides(mesh, topology, threads)) {
        const int next = (side.corner + 1) % 3;
        HoleSide h;
        h.from = topology[side.triangle][next];
        h.to = topology[side.triangle][side.corner];
        h.vertex = mesh.triangles[side.triangle][next];
        h.end_vertex = mesh.triangles[side.triangle][side.corner];
        h.face = mesh.has_face_ids() ? mesh.face_ids[side.triangle] : 0;
        h.index = sides.size();
        sides.push_back(h);
    }
    // Each open side also the other way round, for holes whose boundary a folded
    // neighbour turned (bug32596: two chains from one vertex to another).
    const std::size_t open = sides.size();
    for (std::size_t s = 0; s < open; ++s) {
        HoleSide back = sides[s];
        std::swap(back.from, back.to);
        std::swap(back.vertex, back.end_vertex);
        back.backward = true;
        sides.push_back(back);
    }
    std::multimap<std::int32_t, std::size_t> by_start;
    for (std::size_t s = 0; s < sides.size(); ++s) by_start.emplace(sides[s].from, s);
    std::vector<char> used(open, 0);
    int filled = 0;
    for (std::size_t s = 0; s < open; ++s) {
        if (used[s]) continue;
        const std::vector<HoleSide> cycle = shortest_cycle(mesh, sides, s, by_start, used, max_sides);
        if (cycle.size() < 3 || !(hole_width(mesh, cycle) <= width)) continue;
        for (const HoleSide& h : cycle) used[h.index] = 1;
        for (std::size_t i = 1; i + 1 < cycle.size(); ++i) {
            mesh.triangles.push_back({cycle[0].vertex, cycle[i].vertex, cycle[i + 1].vertex});
            if (mesh.has_face_ids()) mesh.face_ids.push_back(cycle[0].face);
        }
        ++filled;
    }
    return filled;
}

}  // namespace trimkit::tess
