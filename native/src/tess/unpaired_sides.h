// Open boundary of a model mesh in its position topology (snap_boundary_vertices.h),
// side by side. Counting uses per edge is not enough: a face's boundary vertex that
// lies just off its neighbour's chord makes a sliver triangle whose side repeats the
// chord, so the chord is used three times (two by one face, one by the other) and
// one of the uses has no partner. Sides are therefore paired: opposite directions
// within one face first (a face's own triangulation is consistent), then the rest
// across faces, opposite directions before equal ones (faces of a loose model may
// disagree in orientation). What is left over is open.
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "mesh/mesh.h"

namespace trimkit::tess {

// The side of `triangle` from its corner `corner` to corner (corner + 1) % 3.
struct TriangleSide {
    std::int32_t triangle = 0;
    int corner = 0;
};

// One key for the edge between vertices a and b, whichever way it runs.
inline std::uint64_t edge_key(std::int32_t a, std::int32_t b) {
    if (a > b) std::swap(a, b);
    return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

// Sides without a partner, sorted by (triangle, corner). `topology` holds the
// position group of every triangle corner (position_triangles); degenerate sides
// (both ends in one group) are skipped. Without face ids all triangles are one face.
// The pairing within each face runs on `threads` threads; the result does not depend
// on their number.
std::vector<TriangleSide> unpaired_sides(const mesh::Mesh& mesh,
                                         const std::vector<std::array<std::int32_t, 3>>& topology,
                                         int threads = 1);

}  // namespace trimkit::tess
