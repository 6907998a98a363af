#include "tess/unpaired_sides.h"

#include <algorithm>
#include <tuple>

#include "mesh/parallel_for.h"
#include "mesh/parallel_sort.h"

namespace trimkit::tess {
namespace {

struct SideUse {
    std::int32_t lo, hi, face;
    bool forward;  // runs lo -> hi
    TriangleSide side;
    auto key() const { return std::make_tuple(lo, hi, face, forward, side.triangle, side.corner); }
};

bool by_key(const SideUse& x, const SideUse& y) { return x.key() < y.key(); }
bool by_edge(const SideUse& x, const SideUse& y) { return edge_key(x.lo, x.hi) < edge_key(y.lo, y.hi); }
bool same_edge(const SideUse& x, const SideUse& y) { return x.lo == y.lo && x.hi == y.hi; }

// Calls edge(begin, end) for each run of uses of one edge in `uses` (sorted by_edge).
template <class Edge>
void for_each_edge(std::vector<SideUse>& uses, const Edge& edge) {
    for (auto i = uses.begin(); i != uses.end();) {
        auto j = i + 1;
        while (j != uses.end() && same_edge(*j, *i)) ++j;
        edge(i, j);
        i = j;
    }
}

// Pairs forward with backward uses among `uses` (in order); appends the rest to `left`.
void pair_opposite(const std::vector<SideUse>& uses, std::vector<SideUse>& left) {
    std::vector<SideUse> forward, backward;
    for (const SideUse& u : uses) (u.forward ? forward : backward).push_back(u);
    const std::size_t pairs = std::min(forward.size(), backward.size());
    left.insert(left.end(), forward.begin() + pairs, forward.end());
    left.insert(left.end(), backward.begin() + pairs, backward.end());
}

// The uses `group` (one edge) leaves unpaired, in full key order: a plain pair closes
// (whatever its directions); otherwise forward uses pair with backward ones within each
// face, then across faces.
void leftover_of_edge(std::vector<SideUse>::iterator begin, std::vector<SideUse>::iterator end,
                      std::vector<SideUse>& left) {
    if (end - begin == 2) return;
    std::sort(begin, end, by_key);
    std::vector<SideUse> across;
    for (auto f = begin; f != end;) {
        auto g = f + 1;
        while (g != end && g->face == f->face) ++g;
        pair_opposite({f, g}, across);
        f = g;
    }
    pair_opposite(across, left);
}

// The uses of one face's triangles that its own triangulation leaves unpaired: within a
// face, an edge's uses pair forward with backward (a plain pair of one direction stays,
// for the pairing across faces to close).
std::vector<SideUse> face_leftover(const mesh::Mesh& mesh, const std::vector<std::array<std::int32_t, 3>>& topology,
                                   const std::vector<std::int32_t>& triangles) {
    std::vector<SideUse> uses;
    uses.reserve(3 * triangles.size());
    for (std::int32_t t : triangles) {
        const std::int32_t face = mesh.has_face_ids() ? mesh.face_ids[t] : 0;
        for (int k = 0; k < 3; ++k) {
            const std::int32_t a = topology[t][k], b = topology[t][(k + 1) % 3];
            if (a == b) continue;
            uses.push_back({std::min(a, b), std::max(a, b), face, a < b, {t, k}});
        }
    }
    std::sort(uses.begin(), uses.end(), by_edge);
    std::vector<SideUse> left;
    for_each_edge(uses, [&](auto begin, auto end) {
        if (end - begin == 2 && begin->forward != (begin + 1)->forward) return;
        if (end - begin > 2) std::sort(begin, end, by_key);
        pair_opposite({begin, end}, left);
    });
    return left;
}

// Triangles by face: runs of one face id (a model mesh appends face after face), runs
// of the same face joined, faces in id order.
std::vector<std::vector<std::int32_t>> triangles_by_face(const mesh::Mesh& mesh,
                                                        std::size_t count) {
    if (!mesh.has_face_ids()) {
        std::vector<std::int32_t> all(count);
        for (std::size_t t = 0; t < count; ++t) all[t] = static_cast<std::int32_t>(t);
        return {all};
    }
    std::vector<std::pair<std::int32_t, std::size_t>> runs;  // (face, first triangle)
    for (std::size_t t = 0; t < count; ++t)
        if (t == 0 || mesh.face_ids[t] != mesh.face_ids[t - 1]) runs.emplace_back(mesh.face_ids[t], t);
    std::stable_sort(runs.begin(), runs.end(),
                     [](const auto& x, const auto& y) { return x.first < y.first; });
    std::vector<std::vector<std::int32_t>> faces;
    for (std::size_t r = 0; r < runs.size(); ++r) {
        if (r == 0 || runs[r].first != runs[r - 1].first) faces.emplace_back();
        for (std::size_t t = runs[r].second; t < count && mesh.face_ids[t] == runs[r].first; ++t)
            faces.back().push_back(static_cast<std::int32_t>(t));
    }
    return faces;
}

}  // namespace

std::vector<TriangleSide> unpaired_sides(const mesh::Mesh& mesh,
                                         const std::vector<std::array<std::int32_t, 3>>& topology, int threads) {
    // Each face's own pairs first, face by face (in parallel: most sides are inside a
    // face); then the leftovers of all faces, edge by edge, as one would pair them all.
    const std::vector<std::vector<std::int32_t>> faces = triangles_by_face(mesh, topology.size());
    std::vector<std::vector<SideUse>> per_face(faces.size());
    mesh::parallel_for(static_cast<int>(faces.size()), threads,
                       [&](int f) { per_face[f] = face_leftover(mesh, topology, faces[f]); });
    std::vector<SideUse> uses;
    for (const auto& left : per_face) uses.insert(uses.end(), left.begin(), left.end());
    mesh::parallel_sort(uses.begin(), uses.end(), threads, by_edge);

    std::vector<TriangleSide> open;
    for_each_edge(uses, [&](auto begin, auto end) {
        std::vector<SideUse> left;
        leftover_of_edge(begin, end, left);
        // What is left runs one way (faces disagreeing in orientation): pairs of it
        // close, an odd one out stays open.
        if (left.size() % 2 == 1) open.push_back(left.back().side);
    });
    std::sort(open.begin(), open.end(), [](const TriangleSide& x, const TriangleSide& y) {
        return std::tie(x.triangle, x.corner) < std::tie(y.triangle, y.corner);
    });
    return open;
}

}  // namespace trimkit::tess
