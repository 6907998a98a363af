#include "fit/evaluate_fit.h"

#include <algorithm>

#include "fit/boundary_samples.h"
#include "fit/loop_polygons.h"
#include "geom/surface_projector.h"

namespace trimkit::fit {
namespace {

constexpr int kLoopSamplesPerCoedge = 32;
constexpr int kEdgeSamplesPerCoedge = 32;

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

double distance_to(const geom::SurfaceProjector& projector, const Eigen::Vector3d& x) {
    const Eigen::Vector2d uv = projector.invert(x);
    return (projector.surface().evaluate(uv.x(), uv.y()) - x).norm();
}

}  // namespace

FitError evaluate_fit(const geom::Face& source, const std::vector<geom::Edge>& edges, const geom::NurbsSurface& fitted) {
    const geom::SurfaceProjector projector(fitted);
    FitError e;
    Eigen::AlignedBox3d box;
    const std::vector<Eigen::Vector2d> outer = loop_polygon(outer_loop(source));
    const LoopPolygons region({outer});
    Eigen::AlignedBox2d uv_box;
    for (const Eigen::Vector2d& p : outer) uv_box.extend(p);
    double sum = 0;
    for (int i = 0; i <= kErrorGridSections; ++i)
        for (int j = 0; j <= kErrorGridSections; ++j) {
            const Eigen::Vector2d uv = uv_box.min() + (uv_box.max() - uv_box.min()).cwiseProduct(
                                                          Eigen::Vector2d(i, j) / kErrorGridSections);
            if (!region.contains(uv)) continue;
            const Eigen::Vector3d x = source.surface.evaluate(uv.x(), uv.y());
            const double d = distance_to(projector, x);
            box.extend(x);
            sum += d;
            e.surface_max = std::max(e.surface_max, d);
            ++e.grid_points;
        }
    e.surface_avg = e.grid_points ? sum / e.grid_points : 0.0;
    const std::vector<BoundarySample> samples = boundary_samples(source, edges, kEdgeSamplesPerCoedge);
    sum = 0;
    for (const BoundarySample& s : samples) {
        const double d = distance_to(projector, s.x);
        box.extend(s.x);
        sum += d;
        e.edge_max = std::max(e.edge_max, d);
    }
    e.edge_avg = samples.empty() ? 0.0 : sum / samples.size();
    e.box_diagonal = box.isEmpty() ? 0.0 : box.diagonal().norm();
    return e;
}

}  // namespace trimkit::fit
