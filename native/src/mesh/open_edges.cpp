#include "mesh/open_edges.h"

#include <algorithm>
#include <tuple>

namespace trimkit::mesh {
namespace {

// One directed use of an edge by a triangle, keyed by its unordered pair.
struct HalfEdge {
    std::int32_t lo, hi;
    bool forward;  // the triangle runs lo -> hi
    bool operator<(const HalfEdge& o) const {
        return std::tie(lo, hi, forward) < std::tie(o.lo, o.hi, o.forward);
    }
};

}  // namespace

OpenEdges open_edges(const Mesh& mesh) {
    validate(mesh);
    std::vector<HalfEdge> half_edges;
    half_edges.reserve(3 * mesh.triangles.size());
    for (const auto& t : mesh.triangles) {
        for (int k = 0; k < 3; ++k) {
            const std::int32_t a = t[k], b = t[(k + 1) % 3];
            if (a == b) continue;
            half_edges.push_back({std::min(a, b), std::max(a, b), a < b});
        }
    }
    std::sort(half_edges.begin(), half_edges.end());

    OpenEdges result;
    for (std::size_t i = 0; i < half_edges.size();) {
        std::size_t j = i + 1;
        while (j < half_edges.size() && half_edges[j].lo == half_edges[i].lo &&
               half_edges[j].hi == half_edges[i].hi)
            ++j;
        const HalfEdge& h = half_edges[i];
        const auto count = static_cast<std::int32_t>(j - i);
        if (count == 1) {
            result.boundary.push_back(h.forward ? std::array<std::int32_t, 2>{h.lo, h.hi}
                                                : std::array<std::int32_t, 2>{h.hi, h.lo});
        } else if (count == 2) {
            if (half_edges[i].forward == half_edges[i + 1].forward)
                result.misoriented.push_back({h.lo, h.hi});
        } else {
            result.non_manifold.push_back({{h.lo, h.hi}, count});
        }
        i = j;
    }
    return result;
}

std::size_t count_open_edges(const Mesh& mesh) {
    const OpenEdges open = open_edges(mesh);
    std::size_t odd = 0;
    for (const EdgeUses& e : open.non_manifold) odd += e.count % 2;
    return open.boundary.size() + odd;
}

}  // namespace trimkit::mesh
