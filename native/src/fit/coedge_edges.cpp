#include "fit/coedge_edges.h"

#include <algorithm>
#include <optional>
#include <utility>
#include <vector>

#include "fit/fit_curve.h"

namespace trimkit::fit {
namespace {

// (degree, control points) tried in order: a straight line first, then cubics.
constexpr std::pair<int, int> kCurveShapes[] = {{1, 2}, {3, 4}, {3, 8}, {3, 16}, {3, 32}, {3, kMaxFitControlPoints}};
// Samples per control point: enough that the fit is judged between its knots.
constexpr int kSamplesPerPoint = 6;

std::optional<geom::NurbsCurve3d> edge_curve(const geom::NurbsSurface& S, const geom::NurbsCurve2d& c, double tolerance) {
    // Named copies, not a structured binding: a lambda may capture those only from C++20
    // (clang 14 rejects it in C++17 mode; g++ accepts it).
    const auto domain = c.domain();
    const double a = domain.first, b = domain.second;
    const auto image = [&](double s) {
        const Eigen::Vector2d uv = c.evaluate(a + (b - a) * s);
        return S.evaluate(uv.x(), uv.y());
    };
    for (const auto& [degree, count] : kCurveShapes) {
        CurveFitProblem problem;
        problem.degree = degree;
        problem.count = count;
        problem.smoothing = 0;  // samples are plenty (kSamplesPerPoint per control point); the energy would bias them
        const int m = kSamplesPerPoint * std::max(count, 4);
        // Chord-length parameters: rational arcs are only C1 in their own parameter
        // at their knots, which a uniform-knot cubic follows slowly; in arc length
        // the image is as smooth as its geometry.
        std::vector<Eigen::Vector3d> mid;
        for (int k = 0; k <= m; ++k) {
            problem.points.push_back(image(static_cast<double>(k) / m));
            if (k < m) mid.push_back(image((k + 0.5) / m));
        }
        std::vector<double> length(m + 1, 0.0);
        for (int k = 1; k <= m; ++k)
            length[k] = length[k - 1] + (problem.points[k] - mid[k - 1]).norm() + (mid[k - 1] - problem.points[k - 1]).norm();
        if (!(length[m] > 0)) return std::nullopt;  // a degenerate (zero-length) coedge
        for (int k = 0; k <= m; ++k) problem.params.push_back(k == m ? 1.0 : length[k] / length[m]);
        problem.start = problem.points.front();
        problem.end = problem.points.back();
        const geom::NurbsCurve3d curve = fit_curve(problem);
        double worst = 0;
        for (int k = 0; k < m; ++k) {
            const double s = (length[k] + (mid[k] - problem.points[k]).norm()) / length[m];
            worst = std::max(worst, (curve.evaluate(s) - mid[k]).norm());
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
                geom::Edge e;  // no start/end vertices: the curve's ends are the vertices
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
