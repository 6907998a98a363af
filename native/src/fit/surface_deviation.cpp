#include "fit/surface_deviation.h"

#include <algorithm>
#include <vector>

#include "fit/loop_polygons.h"
#include "geom/surface_projector.h"

namespace trimkit::fit {
namespace {

constexpr int kLoopSamplesPerCoedge = 32;

const geom::Loop& outer_loop(const geom::Face& face) {
    for (const geom::Loop& loop : face.loops)
        if (loop.outer) return loop;
    return face.loops.front();
}

std::vector<Eigen::Vector2d> loop_polygon(const geom::Loop& loop) {
    std::vector<Eigen::Vector2d> polygon;
    for (const geom::Coedge& c : loop.coedges) {
        const auto [a, b] = c.curve.domain();
        for (int k = 0; k < kLoopSamplesPerCoedge; ++k) polygon.push_back(c.curve.evaluate(a + (b - a) * k / kLoopSamplesPerCoedge));
    }
    return polygon;
}

}  // namespace

SurfaceDeviation surface_deviation(const geom::Face& source, const geom::NurbsSurface& target) {
    const geom::SurfaceProjector projector(target);
    SurfaceDeviation d;
    const std::vector<Eigen::Vector2d> outer = loop_polygon(outer_loop(source));
    const LoopPolygons region({outer});
    Eigen::AlignedBox2d uv_box;
    for (const Eigen::Vector2d& p : outer) uv_box.extend(p);
    double sum = 0;
    for (int i = 0; i <= kErrorGridSections; ++i)
        for (int j = 0; j <= kErrorGridSections; ++j) {
            const Eigen::Vector2d uv =
                uv_box.min() + (uv_box.max() - uv_box.min()).cwiseProduct(Eigen::Vector2d(i, j) / kErrorGridSections);
            if (!region.contains(uv)) continue;
            const Eigen::Vector3d x = source.surface.evaluate(uv.x(), uv.y());
            // Two Newton starts, the grid's and the source (u, v) (the right one when both
            // faces share a surface, where the grid start can stall on a closed surface);
            // either result is a point of the target, so the nearer is the better bound.
            const Eigen::Vector2d st = projector.invert(x), near = projector.invert(x, &uv);
            const double e = std::min((target.evaluate(st.x(), st.y()) - x).norm(),
                                      (target.evaluate(near.x(), near.y()) - x).norm());
            d.box.extend(x);
            sum += e;
            d.max = std::max(d.max, e);
            ++d.points;
        }
    d.avg = d.points ? sum / d.points : 0.0;
    return d;
}

}  // namespace trimkit::fit
