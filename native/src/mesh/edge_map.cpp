#include "mesh/edge_map.h"

#include <algorithm>
#include <string>

#include "geom/error.h"

namespace trimkit::mesh {

EdgeMap edge_map(const std::vector<std::array<std::int32_t, 3>>& triangles, std::size_t vertex_count) {
    for (std::size_t t = 0; t < triangles.size(); ++t)
        for (std::int32_t v : triangles[t])
            if (v < 0 || static_cast<std::size_t>(v) >= vertex_count)
                throw geom::InvalidInput("edge_map: triangle " + std::to_string(t) + " uses vertex " +
                                         std::to_string(v) + " of " + std::to_string(vertex_count));
    // Corners bucketed by the smaller vertex of their edge (counting sort).
    std::vector<std::uint32_t> start(vertex_count + 1, 0);
    for (const auto& t : triangles)
        for (int k = 0; k < 3; ++k) ++start[std::min(t[k], t[(k + 1) % 3]) + 1];
    for (std::size_t v = 0; v < vertex_count; ++v) start[v + 1] += start[v];
    std::vector<std::uint32_t> bucket(3 * triangles.size()), fill(start.begin(), start.end() - 1);
    for (std::size_t c = 0; c < 3 * triangles.size(); ++c) {
        const auto& t = triangles[c / 3];
        const int k = static_cast<int>(c % 3);
        bucket[fill[std::min(t[k], t[(k + 1) % 3])]++] = static_cast<std::uint32_t>(c);
    }
    // Within a bucket, corners with the same larger vertex share an edge; edges are
    // numbered by their first corner, so the order does not depend on the buckets.
    constexpr std::uint32_t kNone = 0xffffffffu;
    EdgeMap map;
    map.corner_edges.assign(3 * triangles.size(), kNone);
    std::vector<std::uint32_t> first_corner(3 * triangles.size(), kNone);
    for (std::size_t v = 0; v < vertex_count; ++v)
        for (std::uint32_t i = start[v]; i < start[v + 1]; ++i) {
            const std::uint32_t c = bucket[i];
            if (first_corner[c] != kNone) continue;
            const auto& t = triangles[c / 3];
            const std::int32_t hi = std::max(t[c % 3], t[(c % 3 + 1) % 3]);
            for (std::uint32_t j = i; j < start[v + 1]; ++j) {
                const std::uint32_t d = bucket[j];
                const auto& s = triangles[d / 3];
                if (std::max(s[d % 3], s[(d % 3 + 1) % 3]) == hi) first_corner[d] = c;
            }
        }
    std::vector<std::uint32_t> edge_of_corner(3 * triangles.size(), kNone);
    for (std::size_t c = 0; c < 3 * triangles.size(); ++c) {
        const std::uint32_t f = first_corner[c];
        if (edge_of_corner[f] == kNone) {
            const auto& t = triangles[f / 3];
            const std::int32_t a = t[f % 3], b = t[(f % 3 + 1) % 3];
            edge_of_corner[f] = static_cast<std::uint32_t>(map.edges.size());
            map.edges.push_back({static_cast<std::uint32_t>(std::min(a, b)), static_cast<std::uint32_t>(std::max(a, b))});
        }
        map.corner_edges[c] = edge_of_corner[f];
    }
    return map;
}

}  // namespace trimkit::mesh
