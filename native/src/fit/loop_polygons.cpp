#include "fit/loop_polygons.h"

namespace trimkit::fit {

LoopPolygons::LoopPolygons(std::vector<std::vector<Eigen::Vector2d>> polygons) {
    for (auto& p : polygons)
        if (p.size() >= 3) polygons_.push_back(std::move(p));
}

bool LoopPolygons::contains(const Eigen::Vector2d& q) const {
    bool inside = false;
    for (const auto& poly : polygons_)
        for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
            const Eigen::Vector2d& a = poly[i];
            const Eigen::Vector2d& b = poly[j];
            if ((a.y() > q.y()) != (b.y() > q.y()) &&
                q.x() < a.x() + (q.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y()))
                inside = !inside;
        }
    return inside;
}

}  // namespace trimkit::fit
