// Cells of a uniform 3D grid as hash-map keys, for finding points near each other
// (vertex welding, boundary snapping, T-junction closing, sewing, TBP intersection
// points): a point's cell is floor(p / size). The one spatial hash of the library.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include <Eigen/Core>

#include "geom/clamped_int.h"

namespace trimkit::mesh {

struct GridCell {
    std::int64_t x, y, z;
    bool operator==(const GridCell& o) const { return x == o.x && y == o.y && z == o.z; }

    static GridCell of(const Eigen::Vector3d& p, double size) {
        return {index(p.x() / size), index(p.y() / size), index(p.z() / size)};
    }
    // floor(t), clamped to +-2^62 (geom::clamped_int: a double beyond int64's range
    // would be undefined behaviour; such a coordinate is far beyond any model), NaN to 0.
    static std::int64_t index(double t) {
        constexpr std::int64_t kLimit = std::int64_t(1) << 62;
        if (!(t == t)) return 0;
        return geom::clamped_int(std::floor(t), -kLimit, kLimit);
    }
};

struct GridCellHash {
    std::size_t operator()(const GridCell& k) const {
        // Large odd multipliers spread neighbouring cells (Teschner et al. 2003 style).
        const auto h = static_cast<std::uint64_t>(k.x) * 73856093ULL ^ static_cast<std::uint64_t>(k.y) * 19349663ULL ^
                       static_cast<std::uint64_t>(k.z) * 83492791ULL;
        return static_cast<std::size_t>(h ^ (h >> 29));
    }
};

}  // namespace trimkit::mesh
