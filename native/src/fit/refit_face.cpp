#include "fit/refit_face.h"

#include <string>

#include "fit/boundary_curves.h"
#include "fit/boundary_samples.h"
#include "fit/coons_fill.h"
#include "fit/corner_normals.h"
#include "fit/fit_surface.h"
#include "fit/loop_polygons.h"
#include "fit/neighbour_normals.h"
#include "fit/outside_samples.h"
#include "geom/error.h"

namespace trimkit::fit {
namespace {

int outer_loop(const geom::Face& face) {
    for (std::size_t l = 0; l < face.loops.size(); ++l)
        if (face.loops[l].outer) return static_cast<int>(l);
    return 0;
}

bool is_g1(const FitRule& rule, const BoundarySample& s) {
    return s.loop < static_cast<int>(rule.g1.size()) && s.coedge < static_cast<int>(rule.g1[s.loop].size()) &&
           rule.g1[s.loop][s.coedge];
}

// The tangent plane's normal at each sample, oriented like frame.n.
std::vector<Eigen::Vector3d> sample_normals(const geom::Model& model, const EdgeFaces& uses, int face,
                                            const FitRule& rule, const std::vector<BoundarySample>& samples,
                                            const LocalFrame& frame) {
    NeighbourNormals neighbours(model, uses, face);
    const std::vector<std::optional<Eigen::Vector3d>> from_corners = corner_normals(samples, frame.n);
    std::vector<Eigen::Vector3d> normals;
    for (std::size_t k = 0; k < samples.size(); ++k) {
        const BoundarySample& s = samples[k];
        Eigen::Vector3d n;
        if (is_g1(rule, s)) {
            n = neighbours.at(s.loop, s.coedge, s.x);
        } else {
            // The corners' tangent plane (corner_normals), else the plane through t closest to the reference plane.
            const Eigen::Vector3d guess = from_corners[k] ? *from_corners[k] : frame.n;
            n = guess - guess.dot(s.tangent) * s.tangent;
            if (!(n.norm() > 1e-6)) n = s.tangent.unitOrthogonal();
        }
        n.normalize();
        normals.push_back(n.dot(frame.n) < 0 ? Eigen::Vector3d(-n) : n);
    }
    return normals;
}

LoopPolygons projected_loops(const std::vector<BoundarySample>& samples, const LocalFrame& frame) {
    std::vector<std::vector<Eigen::Vector2d>> polygons;
    for (const BoundarySample& s : samples) {
        if (polygons.size() <= static_cast<std::size_t>(s.loop)) polygons.resize(s.loop + 1);
        polygons[s.loop].push_back(frame.plane(s.x));
    }
    return LoopPolygons(std::move(polygons));
}

}  // namespace

RefitResult refit_face(const geom::Model& model, const EdgeFaces& uses, int face, const FitRule& rule) {
    if (rule.method == FitMethod::kCoons) return {coons_fill(model, uses, face, rule), LocalFrame{}};
    const geom::Face& f = model.faces[face];
    const std::vector<BoundarySample> samples = boundary_samples(f, model.edges, kBoundarySamplesPerCoedge);
    const LocalFrame frame = local_frame(samples, outer_loop(f));
    const std::vector<Eigen::Vector3d> normals = sample_normals(model, uses, face, rule, samples, frame);
    const OutsideSamples outside = outside_samples(samples, normals, frame, projected_loops(samples, frame));

    SurfaceFitProblem problem;
    problem.degree_u = rule.degree_u, problem.degree_v = rule.degree_v;
    problem.count_u = rule.count_u, problem.count_v = rule.count_v;
    problem.smoothing = kSurfaceSmoothing;
    problem.tangent_weight = kG1Weight;
    for (std::size_t k = 0; k < samples.size(); ++k) {
        const Eigen::Vector2d uv = frame.uv(samples[k].x).cwiseMax(0.0).cwiseMin(1.0);
        problem.points.push_back({uv, samples[k].x, kBoundaryWeight});
        if (is_g1(rule, samples[k])) problem.tangent_planes.push_back({uv, normals[k], 1.0});
    }
    problem.points.insert(problem.points.end(), outside.points.begin(), outside.points.end());
    if (rule.boundary_curves)
        problem.fixed = boundary_rows(boundary_curves(outside, rule), rule.count_u, rule.count_v);
    return {fit_surface(problem), frame};
}

}  // namespace trimkit::fit
