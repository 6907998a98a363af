#include "tess/unpaired_sides.h"

#include <algorithm>
#include <tuple>

namespace trimkit::tess {
namespace {

struct SideUse {
    std::int32_t lo, hi, face;
    bool forward;  // runs lo -> hi
    TriangleSide side;
    auto key() const { return std::make_tuple(lo, hi, face, forward, side.triangle, side.corner); }
};

// Pairs forward with backward uses among `uses` (in order); appends the rest to `left`.
void pair_opposite(const std::vector<SideUse>& uses, std::vector<SideUse>& left) {
    std::vector<SideUse> forward, backward;
    for (const SideUse& u : uses) (u.forward ? forward : backward).push_back(u);
    const std::size_t pairs = std::min(forward.size(), backward.size());
    left.insert(left.end(), forward.begin() + pairs, forward.end());
    left.insert(left.end(), backward.begin() + pairs, backward.end());
}

}  // namespace

std::vector<TriangleSide> unpaired_sides(const mesh::Mesh& mesh,
                                         const std::vector<std::array<std::int32_t, 3>>& topology) {
    std::vector<SideUse> uses;
    uses.reserve(3 * topology.size());
    for (std::size_t t = 0; t < topology.size(); ++t) {
        const std::int32_t face = mesh.has_face_ids() ? mesh.face_ids[t] : 0;
        for (int k = 0; k < 3; ++k) {
            const std::int32_t a = topology[t][k], b = topology[t][(k + 1) % 3];
            if (a == b) continue;
            uses.push_back({std::min(a, b), std::max(a, b), face, a < b, {static_cast<std::int32_t>(t), k}});
        }
    }
    // Grouped by edge with a cheap key first; only the rare groups that are not a plain
    // pair are put in full key order, which is all the pairing below depends on.
    std::sort(uses.begin(), uses.end(),
              [](const SideUse& x, const SideUse& y) { return edge_key(x.lo, x.hi) < edge_key(y.lo, y.hi); });

    std::vector<TriangleSide> open;
    for (std::size_t i = 0; i < uses.size();) {
        std::size_t j = i + 1;
        while (j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi) ++j;
        if (j - i == 2) {  // the common case: two uses close the edge, whatever their directions
            i = j;
            continue;
        }
        std::sort(uses.begin() + i, uses.begin() + j,
                  [](const SideUse& x, const SideUse& y) { return x.key() < y.key(); });
        // Within each face, then across faces.
        std::vector<SideUse> across;
        for (std::size_t f = i; f < j;) {
            std::size_t g = f + 1;
            while (g < j && uses[g].face == uses[f].face) ++g;
            pair_opposite({uses.begin() + f, uses.begin() + g}, across);
            f = g;
        }
        std::vector<SideUse> left;
        pair_opposite(across, left);
        // What is left runs one way (faces disagreeing in orientation): pairs of it
        // close, an odd one out stays open.
        if (left.size() % 2 == 1) open.push_back(left.back().side);
        i = j;
    }
    std::sort(open.begin(), open.end(), [](const TriangleSide& x, const TriangleSide& y) {
        return std::tie(x.triangle, x.corner) < std::tie(y.triangle, y.corner);
    });
    return open;
}

}  // namespace trimkit::tess
