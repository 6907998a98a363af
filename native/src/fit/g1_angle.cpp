#include "fit/g1_angle.h"

#include <algorithm>
#include <cmath>

#include "fit/boundary_samples.h"
#include "fit/neighbour_normals.h"
#include "geom/surface_projector.h"

namespace trimkit::fit {

std::vector<G1Sample> g1_samples(const geom::Model& model, const EdgeFaces& uses, int face, const FitRule& rule,
                                 const geom::NurbsSurface& surface) {
    const geom::SurfaceProjector own(surface);
    NeighbourNormals neighbours(model, uses, face);
    std::vector<G1Sample> out;
    for (std::size_t l = 0; l < rule.g1.size(); ++l)
        for (std::size_t c = 0; c < rule.g1[l].size(); ++c) {
            if (!rule.g1[l][c]) continue;
            const geom::Coedge& coedge = model.faces[face].loops[l].coedges[c];
            for (int k = 0; k < kG1CheckSamples; ++k) {
                G1Sample s;
                s.loop = static_cast<int>(l);
                s.coedge = static_cast<int>(c);
                s.point = coedge_point(model.edges, coedge, static_cast<double>(k) / (kG1CheckSamples - 1));
                const Eigen::Vector2d uv = own.invert(s.point);
                s.normal = surface.normal(uv.x(), uv.y());
                s.neighbour_normal = neighbours.at(s.loop, s.coedge, s.point).normalized();
                const double dot = std::abs(s.normal.dot(s.neighbour_normal));
                s.angle = std::acos(std::min(1.0, dot)) * 180.0 / M_PI;
                out.push_back(s);
            }
        }
    return out;
}

double g1_angle(const geom::Model& model, const EdgeFaces& uses, int face, const FitRule& rule,
                const geom::NurbsSurface& surface) {
    double worst = 0;
    for (const G1Sample& s : g1_samples(model, uses, face, rule, surface)) worst = std::max(worst, s.angle);
    return worst;
}

}  // namespace trimkit::fit
