#include "tess/corner_attributes.h"

#include <cmath>
#include <memory>
#include <string>

#include "geom/error.h"
#include "geom/surface_projector.h"

namespace trimkit::tess {
namespace {

// A vertex's own (u,v) counts as a good Newton start on another face when S(uv)
// lies within this fraction of the surface size of the vertex: the two faces then
// share the parameterization locally (planar patches split from one surface).
constexpr double kNearStartRelative = 1e-3;

// Moves the corners of one triangle on the minority side of a seam by one period
// in coordinate `c` (0 = u, 1 = v), so the (u,v) triangle does not span the domain.
void unwrap_seam(Eigen::Vector2d* uv, int c, double lo, double hi) {
    const double period = hi - lo;
    if (!(period > 0.0)) return;
    double min = uv[0][c], max = uv[0][c];
    for (int k = 1; k < 3; ++k) min = std::min(min, uv[k][c]), max = std::max(max, uv[k][c]);
    if (max - min <= 0.5 * period) return;
    const double mid = lo + 0.5 * period;
    int below = 0;
    for (int k = 0; k < 3; ++k) below += uv[k][c] < mid;
    for (int k = 0; k < 3; ++k) {
        if (below >= 2 && uv[k][c] >= mid) uv[k][c] -= period;
        if (below < 2 && uv[k][c] < mid) uv[k][c] += period;
    }
}

}  // namespace

CornerAttributes corner_attributes(const geom::Model& model, const mesh::Mesh& mesh) {
    const std::size_t T = mesh.triangle_count(), V = mesh.vertex_count();
    if (!mesh.has_face_ids() || !mesh.has_uvs() || !mesh.has_normals())
        throw geom::InvalidInput("corner_attributes: the mesh needs face ids, uvs and normals");
    for (std::size_t t = 0; t < T; ++t)
        if (mesh.face_ids[t] < 0 || static_cast<std::size_t>(mesh.face_ids[t]) >= model.faces.size())
            throw geom::InvalidInput("corner_attributes: face_ids[" + std::to_string(t) + "] = " +
                                     std::to_string(mesh.face_ids[t]) + "; the model has " +
                                     std::to_string(model.faces.size()) + " faces");

    // Vertices used by triangles of more than one face.
    std::vector<int> owner(V, -1);
    std::vector<char> shared(V, 0);
    for (std::size_t t = 0; t < T; ++t)
        for (int v : mesh.triangles[t]) {
            if (owner[v] < 0) owner[v] = mesh.face_ids[t];
            else if (owner[v] != mesh.face_ids[t]) shared[v] = 1;
        }

    std::vector<std::unique_ptr<geom::SurfaceProjector>> projectors(model.faces.size());
    auto projector = [&](int f) -> const geom::SurfaceProjector& {
        if (!projectors[f]) projectors[f] = std::make_unique<geom::SurfaceProjector>(model.faces[f].surface);
        return *projectors[f];
    };

    CornerAttributes out;
    out.uvs.resize(3 * T);
    out.normals.resize(3 * T);
    for (std::size_t t = 0; t < T; ++t) {
        const int f = mesh.face_ids[t];
        const geom::Face& face = model.faces[f];
        const geom::SurfaceProjector& P = projector(f);
        const auto& tri = mesh.triangles[t];
        const Eigen::Vector2d* start = nullptr;
        for (int k = 0; k < 3; ++k)
            if (!shared[tri[k]]) start = &mesh.uvs[tri[k]];
        Eigen::Vector2d uv[3];
        for (int k = 0; k < 3; ++k) {
            const int v = tri[k];
            out.normals[3 * t + k] = mesh.normals[v];
            if (!shared[v]) {
                uv[k] = mesh.uvs[v];
                continue;
            }
            const Eigen::Vector3d& x = mesh.positions[v];
            const Eigen::Vector2d own = mesh.uvs[v];
            const bool own_fits = (face.surface.evaluate(own.x(), own.y()) - x).norm() <= kNearStartRelative * P.size();
            uv[k] = P.invert(x, start ? start : own_fits ? &own : nullptr);
            try {
                const Eigen::Vector3d n = face.surface.normal(uv[k].x(), uv[k].y());
                out.normals[3 * t + k] = face.reversed ? Eigen::Vector3d(-n) : n;
            } catch (const geom::NumericalFailure&) {
                // Degenerate point (pole, apex): keep the welded vertex's normal.
            }
        }
        if (P.closed_u()) unwrap_seam(uv, 0, face.surface.domain_u().first, face.surface.domain_u().second);
        if (P.closed_v()) unwrap_seam(uv, 1, face.surface.domain_v().first, face.surface.domain_v().second);
        for (int k = 0; k < 3; ++k) out.uvs[3 * t + k] = uv[k];
    }
    return out;
}

}  // namespace trimkit::tess
