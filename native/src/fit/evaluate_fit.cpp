#include "fit/evaluate_fit.h"

#include <algorithm>

#include "fit/boundary_samples.h"
#include "fit/surface_deviation.h"
#include "geom/surface_projector.h"

namespace trimkit::fit {
namespace {

constexpr int kEdgeSamplesPerCoedge = 32;

}  // namespace

FitError evaluate_fit(const geom::Face& source, const std::vector<geom::Edge>& edges, const geom::NurbsSurface& fitted) {
    FitError e;
    const SurfaceDeviation grid = surface_deviation(source, fitted);
    e.surface_avg = grid.avg;
    e.surface_max = grid.max;
    e.grid_points = grid.points;
    Eigen::AlignedBox3d box = grid.box;
    const geom::SurfaceProjector projector(fitted);
    const std::vector<BoundarySample> samples = boundary_samples(source, edges, kEdgeSamplesPerCoedge);
    double sum = 0;
    for (const BoundarySample& s : samples) {
        const Eigen::Vector2d uv = projector.invert(s.x);
        const double d = (fitted.evaluate(uv.x(), uv.y()) - s.x).norm();
        box.extend(s.x);
        sum += d;
        e.edge_max = std::max(e.edge_max, d);
    }
    e.edge_avg = samples.empty() ? 0.0 : sum / samples.size();
    e.box_diagonal = box.isEmpty() ? 0.0 : box.diagonal().norm();
    return e;
}

}  // namespace trimkit::fit
