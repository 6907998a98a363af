#include "fit/g1_angle.h"

#include <algorithm>
#include <cmath>

#include "fit/boundary_samples.h"
#include "fit/neighbour_normals.h"
#include "geom/surface_projector.h"

namespace trimkit::fit {

double g1_angle(const geom::Model& model, const EdgeFaces& uses, int face, const FitRule& rule,
                const geom::NurbsSurface& surface) {
    const geom::SurfaceProjector own(surface);
    NeighbourNormals neighbours(model, uses, face);
    double worst = 0;
    for (std::size_t l = 0; l < rule.g1.size(); ++l)
        for (std::size_t c = 0; c < rule.g1[l].size(); ++c) {
            if (!rule.g1[l][c]) continue;
            const geom::Coedge& coedge = model.faces[face].loops[l].coedges[c];
            for (int k = 0; k < kG1CheckSamples; ++k) {
                const Eigen::Vector3d x = coedge_point(model.edges, coedge, static_cast<double>(k) / (kG1CheckSamples - 1));
                const Eigen::Vector2d uv = own.invert(x);
                const double dot = std::abs(surface.normal(uv.x(), uv.y()).dot(
                    neighbours.at(static_cast<int>(l), static_cast<int>(c), x).normalized()));
                worst = std::max(worst, std::acos(std::min(1.0, dot)) * 180.0 / M_PI);
            }
        }
    return worst;
}

}  // namespace trimkit::fit
