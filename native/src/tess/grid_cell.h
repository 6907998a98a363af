// Cells of a uniform 3D grid as hash-map keys, for finding points near each other
// (boundary snapping, T-junction closing): a point's cell is floor(p / size).
#pragma once

#include <cmath>
#include <cstddef>

#include <Eigen/Core>

namespace trimkit::tess {

struct GridCell {
    long long x, y, z;
    bool operator==(const GridCell& o) const { return x == o.x && y == o.y && z == o.z; }

    static GridCell of(const Eigen::Vector3d& p, double size) {
        return {static_cast<long long>(std::floor(p.x() / size)), static_cast<long long>(std::floor(p.y() / size)),
                static_cast<long long>(std::floor(p.z() / size))};
    }
};

struct GridCellHash {
    std::size_t operator()(const GridCell& k) const {
        return static_cast<std::size_t>(k.x * 73856093LL ^ k.y * 19349663LL ^ k.z * 83492791LL);
    }
};

}  // namespace trimkit::tess
