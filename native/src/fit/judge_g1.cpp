#include "fit/judge_g1.h"

#include <cmath>

#include "geom/surface_projector.h"

namespace trimkit::fit {
namespace {

bool normals_agree(const geom::NurbsCurve3d& curve, const geom::SurfaceProjector& a, const geom::SurfaceProjector& b,
                   double angle) {
    const auto [t0, t1] = curve.domain();
    for (int k = 0; k < kG1JudgeSamples; ++k) {
        const double t = t0 + (t1 - t0) * (k + 0.5) / kG1JudgeSamples;
        const Eigen::Vector3d x = curve.evaluate(t);
        const Eigen::Vector2d ua = a.invert(x), ub = b.invert(x);
        const double c = std::abs(a.surface().normal(ua.x(), ua.y()).dot(b.surface().normal(ub.x(), ub.y())));
        if (!(c >= std::cos(angle))) return false;
    }
    return true;
}

}  // namespace

std::vector<std::vector<bool>> judge_g1(const geom::Model& model, const EdgeFaces& uses, int face, double angle) {
    const geom::Face& f = model.faces[face];
    const geom::SurfaceProjector own(f.surface);
    std::vector<std::vector<bool>> g1(f.loops.size());
    for (std::size_t l = 0; l < f.loops.size(); ++l)
        for (std::size_t c = 0; c < f.loops[l].coedges.size(); ++c) {
            const int other = neighbour_face(model, uses, face, static_cast<int>(l), static_cast<int>(c));
            const geom::Edge* edge = f.loops[l].coedges[c].edge >= 0 ? &model.edges[f.loops[l].coedges[c].edge] : nullptr;
            bool smooth = false;
            if (other >= 0 && edge && edge->curve) {
                const geom::SurfaceProjector neighbour(model.faces[other].surface);
                try {
                    smooth = normals_agree(*edge->curve, own, neighbour, angle);
                } catch (const std::exception&) {
                    smooth = false;  // a degenerate normal: not judged G1
                }
            }
            g1[l].push_back(smooth);
        }
    return g1;
}

}  // namespace trimkit::fit
