// LoopPolygons: closed 2D polygons (trim loops sampled in (u, v), or boundary
// samples projected on a reference plane) and even-odd membership: a point is
// inside when a ray in +x crosses the polygons an odd number of times, so loop
// orientation does not matter and holes are outside.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace trimkit::fit {

class LoopPolygons {
public:
    // Each polygon's last point is not repeated; polygons with < 3 points are ignored.
    explicit LoopPolygons(std::vector<std::vector<Eigen::Vector2d>> polygons);
    bool contains(const Eigen::Vector2d& p) const;
    const std::vector<std::vector<Eigen::Vector2d>>& polygons() const { return polygons_; }

private:
    std::vector<std::vector<Eigen::Vector2d>> polygons_;
};

}  // namespace trimkit::fit
