#include "fit/coons_fill.h"

#include <string>

#include "fit/boundary_samples.h"
#include "fit/fit_surface.h"
#include "fit/neighbour_normals.h"
#include "fit/refit_face.h"
#include "geom/error.h"

namespace trimkit::fit {

bool coons_applicable(const geom::Face& face, const std::vector<geom::Edge>& edges) {
    if (face.loops.size() != 1 || face.loops[0].coedges.size() != 4) return false;
    for (const geom::Coedge& c : face.loops[0].coedges)
        if (c.edge < 0 || c.edge >= static_cast<int>(edges.size()) || !edges[c.edge].curve) return false;
    return true;
}

geom::NurbsSurface coons_fill(const geom::Model& model, const EdgeFaces& uses, int face, const FitRule& rule) {
    const geom::Face& f = model.faces[face];
    if (!coons_applicable(f, model.edges))
        throw geom::InvalidInput("coons_fill: face " + std::to_string(face) + " is not one loop of four edges");
    const auto& c = f.loops[0].coedges;
    const auto C = [&](int k, double s) { return coedge_point(model.edges, c[k], s); };
    // Corners P00, P10, P11, P01: the ends of the two coedges meeting there, averaged.
    const Eigen::Vector3d P00 = 0.5 * (C(0, 0) + C(3, 1)), P10 = 0.5 * (C(0, 1) + C(1, 0));
    const Eigen::Vector3d P11 = 0.5 * (C(1, 1) + C(2, 0)), P01 = 0.5 * (C(2, 1) + C(3, 0));
    SurfaceFitProblem problem;
    problem.degree_u = rule.degree_u, problem.degree_v = rule.degree_v;
    problem.count_u = rule.count_u, problem.count_v = rule.count_v;
    problem.smoothing = 1e-9;  // the grid determines every point; the energy only breaks ties
    problem.tangent_weight = kG1Weight;
    NeighbourNormals neighbours(model, uses, face);
    const auto g1 = [&](int k) { return !rule.g1.empty() && rule.g1[0].size() == 4 && rule.g1[0][k]; };
    for (int i = 0; i <= kCoonsGrid; ++i)
        for (int j = 0; j <= kCoonsGrid; ++j) {
            const double u = static_cast<double>(i) / kCoonsGrid, v = static_cast<double>(j) / kCoonsGrid;
            const Eigen::Vector3d x = (1 - v) * C(0, u) + v * C(2, 1 - u) + (1 - u) * C(3, 1 - v) + u * C(1, v) -
                                      ((1 - u) * (1 - v) * P00 + u * (1 - v) * P10 + u * v * P11 + (1 - u) * v * P01);
            problem.points.push_back({{u, v}, x, 1.0});
            // Boundary points of G1 coedges get the neighbour's tangent plane.
            const int side = j == 0 ? 0 : i == kCoonsGrid ? 1 : j == kCoonsGrid ? 2 : i == 0 ? 3 : -1;
            if (side >= 0 && g1(side)) problem.tangent_planes.push_back({{u, v}, neighbours.at(0, side, x).normalized(), 1.0});
        }
    return fit_surface(problem);
}

}  // namespace trimkit::fit
