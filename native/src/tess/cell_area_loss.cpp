#include "tess/cell_area_loss.h"

#include <cmath>
#include <cstdint>
#include <unordered_set>

#include "tess/surface_evaluator.h"
#include "tess/unpaired_sides.h"

namespace trimkit::tess {
namespace {

double triangle_loss(SurfaceEvaluator& evaluator, const mesh::Mesh& m, const std::array<std::int32_t, 3>& t) {
    return triangle_area_loss(evaluator, {m.uvs[t[0]], m.uvs[t[1]], m.uvs[t[2]]},
                              {m.positions[t[0]], m.positions[t[1]], m.positions[t[2]]});
}

// The lens between the chord a-b and S over the (u,v) chord, positive when S bulges
// away from the triangle's third vertex c.
double boundary_lens(SurfaceEvaluator& evaluator, const mesh::Mesh& m, int a, int b, int c) {
    const Eigen::Vector2d mid_uv = 0.5 * (m.uvs[a] + m.uvs[b]);
    Eigen::Vector3d mid, Su, Sv;
    evaluator.evaluate(mid_uv.x(), mid_uv.y(), mid, Su, Sv);
    const Eigen::Vector3d chord = m.positions[b] - m.positions[a];
    const double length = chord.norm();
    if (!(length > 0.0)) return 0.0;
    const Eigen::Vector3d along = chord / length;
    const Eigen::Vector3d to_c = m.positions[c] - m.positions[a];
    Eigen::Vector3d outward = -(to_c - to_c.dot(along) * along);
    if (!(outward.norm() > 0.0)) return 0.0;
    outward.normalize();
    const Eigen::Vector3d offset = mid - 0.5 * (m.positions[a] + m.positions[b]);
    return 2.0 / 3.0 * length * offset.dot(outward);
}

}  // namespace

// The degree-2 rule: barycentric (2/3, 1/6, 1/6) and its permutations, weight 1/3 each.
double triangle_area_loss(SurfaceEvaluator& evaluator, const std::array<Eigen::Vector2d, 3>& uv,
                          const std::array<Eigen::Vector3d, 3>& xyz) {
    constexpr double kNear = 2.0 / 3.0, kFar = 1.0 / 6.0;
    const Eigen::Vector2d ab = uv[1] - uv[0], ac = uv[2] - uv[0];
    const double uv_area = 0.5 * std::abs(ab.x() * ac.y() - ab.y() * ac.x());
    double element = 0.0;
    for (int k = 0; k < 3; ++k) {
        const Eigen::Vector2d p = kNear * uv[k] + kFar * (uv[(k + 1) % 3] + uv[(k + 2) % 3]);
        Eigen::Vector3d P, Su, Sv;
        evaluator.evaluate(p.x(), p.y(), P, Su, Sv);
        element += Su.cross(Sv).norm() / 3.0;
    }
    const double flat = 0.5 * (xyz[1] - xyz[0]).cross(xyz[2] - xyz[0]).norm();
    return uv_area * element - flat;
}

double cell_area_loss(const geom::NurbsSurface& S, const mesh::Mesh& face_mesh) {
    const mesh::Mesh& m = face_mesh;
    if (m.uvs.size() != m.positions.size()) return 0.0;
    std::unordered_set<std::uint64_t> boundary;
    for (const mesh::FlaggedEdge& e : m.edges)
        if (e.flags & mesh::kFaceBoundary) boundary.insert(edge_key(e.v0, e.v1));
    SurfaceEvaluator evaluator(S);
    double loss = 0.0;
    for (const auto& t : m.triangles) {
        double triangle = triangle_loss(evaluator, m, t);
        for (int k = 0; k < 3; ++k) {
            const int a = t[k], b = t[(k + 1) % 3];
            if (boundary.count(edge_key(a, b))) triangle -= boundary_lens(evaluator, m, a, b, t[(k + 2) % 3]);
        }
        if (std::isfinite(triangle)) loss += triangle;
    }
    return loss;
}

}  // namespace trimkit::tess
