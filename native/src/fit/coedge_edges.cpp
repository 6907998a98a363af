#include "fit/coedge_edges.h"

#include <optional>

#include "fit/fit_curve.h"

namespace trimkit::fit {
namespace {

constexpr int kCurveCounts[] = {4, 8, 16, 32, kMaxFitControlPoints};
// Samples per control point: enough that the fit is judged between its knots.
constexpr int kSamplesPerPoint = 6;

std::optional<geom::NurbsCurve3d> edge_curve(const geom::NurbsSurface& S, const geom::NurbsCurve2d& c, double tolerance) {
    const auto [a, b] = c.domain();
    const auto image = [&](double s) {
        const Eigen::Vector2d uv = c.evaluate(a + (b - a) * s);
        return S.evaluate(uv.x(), uv.y());
    };
    for (const int count : kCurveCounts) {
        CurveFitProblem problem;
        problem.count = count;
        const int m = kSamplesPerPoint * count;
        for (int k = 0; k <= m; ++k) {
            problem.params.push_back(static_cast<double>(k) / m);
            problem.points.push_back(image(static_cast<double>(k) / m));
        }
        problem.start = problem.points.front();
        problem.end = problem.points.back();
        const geom::NurbsCurve3d curve = fit_curve(problem);
        double worst = 0;
        for (int k = 0; k < m; ++k) {
            const double s = (k + 0.5) / m;
            worst = std::max(worst, (curve.evaluate(s) - image(s)).norm());
        }
        if (worst <= tolerance) return curve;
    }
    return std::nullopt;
}

}  // namespace

bool add_coedge_edges(geom::Model& model, int face, double tolerance) {
    geom::Face f = model.faces[face];
    std::vector<geom::Edge> edges = model.edges;
    for (geom::Loop& loop : f.loops)
        for (geom::Coedge& coedge : loop.coedges) {
            const bool shared = coedge.edge >= 0 && coedge.edge < static_cast<int>(edges.size());
            if (shared && edges[coedge.edge].curve) continue;
            auto curve = edge_curve(f.surface, coedge.curve, tolerance);
            if (!curve) return false;
            if (shared) {
                edges[coedge.edge].curve = coedge.edge_reversed ? curve->reversed() : *curve;
            } else {
                geom::Edge e;
                e.start = curve->points().front();
                e.end = curve->points().back();
                e.curve = std::move(*curve);
                coedge.edge = static_cast<int>(edges.size());
                coedge.edge_reversed = false;
                edges.push_back(std::move(e));
            }
        }
    model.faces[face] = std::move(f);
    model.edges = std::move(edges);
    return true;
}

}  // namespace trimkit::fit
