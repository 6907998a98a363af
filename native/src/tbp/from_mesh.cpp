#include "tbp/from_mesh.h"

#include <algorithm>
#include <array>
#include <map>
#include <utility>
#include <vector>
#include <cmath>
#include <memory>
#include <string>

#include "geom/error.h"
#include "mesh/weld_vertices.h"
#include "tbp/polygonize.h"

#include <Eigen/LU>

#ifdef TRIMKIT_HAVE_OPENSUBDIV
#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>
#endif

namespace trimkit::tbp {
namespace {

// The input's positions and triangles, validated and welded (coincident corners become
// one vertex); `what` names the caller in errors. `map`, if given, receives the welded
// index of every input vertex.
mesh::Mesh welded_cage(const mesh::Mesh& input, const char* what, std::vector<std::int32_t>* map = nullptr) {
    mesh::validate(input);
    if (input.triangles.empty()) throw geom::InvalidInput(std::string(what) + ": the mesh has no triangles");
    mesh::Mesh m;
    m.positions = input.positions;
    m.triangles = input.triangles;
    mesh::WeldOptions weld;
    weld.tolerance = kWeldRelativeTolerance * mesh::bounding_box(m).diagonal().norm();
    mesh::WeldResult result = mesh::weld_vertices(m, weld);
    if (map) *map = std::move(result.vertex_map);
    return m;
}

}  // namespace

namespace {

// Union-find over triangle corners (3 t + c).
struct Corners {
    std::vector<int> parent;
    explicit Corners(std::size_t n) : parent(n) {
        for (std::size_t i = 0; i < n; ++i) parent[i] = static_cast<int>(i);
    }
    int root(int i) {
        while (parent[i] != i) i = parent[i] = parent[parent[i]];
        return i;
    }
    void join(int a, int b) { parent[root(a)] = root(b); }
};

Eigen::Vector3d face_normal(const mesh::Mesh& m, const std::array<std::int32_t, 3>& t) {
    return (m.positions[t[1]] - m.positions[t[0]]).cross(m.positions[t[2]] - m.positions[t[0]]);
}

int corner_of(const std::array<std::int32_t, 3>& t, std::int32_t v) {
    return t[0] == v ? 0 : t[1] == v ? 1 : 2;
}

// Per triangle corner: whether each side (c, c+1) is sharp, and the corner's unit
// normal, angle-weighted over the triangles around its vertex that no sharp side
// separates from it (a smooth vertex: all of them, as [VPBM01]).
struct CornerNormals {
    std::vector<std::array<bool, 3>> sharp_side;
    std::vector<Eigen::Vector3d> normal;  // 3 t + c
};

// Sides marked sharp: sorted (min, max) welded vertex pairs.
using SidePairs = std::vector<std::pair<std::int32_t, std::int32_t>>;

CornerNormals corner_normals(const mesh::Mesh& m, double sharp_angle, const SidePairs& marked) {
    const std::size_t nt = m.triangles.size();
    CornerNormals out{std::vector<std::array<bool, 3>>(nt, {false, false, false}),
                      std::vector<Eigen::Vector3d>(3 * nt, Eigen::Vector3d::Zero())};
    std::map<std::pair<std::int32_t, std::int32_t>, std::vector<std::pair<int, int>>> sides;  // (triangle, side)
    for (std::size_t t = 0; t < nt; ++t)
        for (int c = 0; c < 3; ++c) {
            const std::int32_t a = m.triangles[t][c], b = m.triangles[t][(c + 1) % 3];
            sides[{std::min(a, b), std::max(a, b)}].push_back({static_cast<int>(t), c});
        }
    const double cos_sharp = std::cos(sharp_angle);
    Corners corners(3 * nt);
    for (const auto& [edge, users] : sides) {
        if (users.size() != 2) continue;  // open or non-manifold: each side keeps its own normals
        const auto [t1, c1] = users[0];
        const auto [t2, c2] = users[1];
        const Eigen::Vector3d n1 = face_normal(m, m.triangles[t1]), n2 = face_normal(m, m.triangles[t2]);
        const double norms = n1.norm() * n2.norm();
        const bool by_angle = sharp_angle < M_PI && norms > 0 && n1.dot(n2) < cos_sharp * norms;
        if (by_angle || std::binary_search(marked.begin(), marked.end(), edge)) {
            out.sharp_side[t1][c1] = out.sharp_side[t2][c2] = true;
            continue;
        }
        for (const std::int32_t v : {edge.first, edge.second})
            corners.join(3 * t1 + corner_of(m.triangles[t1], v), 3 * t2 + corner_of(m.triangles[t2], v));
    }
    std::vector<Eigen::Vector3d> sum(3 * nt, Eigen::Vector3d::Zero());
    for (std::size_t t = 0; t < nt; ++t) {
        const Eigen::Vector3d n = face_normal(m, m.triangles[t]);
        if (n.norm() == 0) continue;
        for (int c = 0; c < 3; ++c) {
            const auto& tri = m.triangles[t];
            const Eigen::Vector3d e1 = m.positions[tri[(c + 1) % 3]] - m.positions[tri[c]];
            const Eigen::Vector3d e2 = m.positions[tri[(c + 2) % 3]] - m.positions[tri[c]];
            sum[corners.root(static_cast<int>(3 * t + c))] += std::atan2(e1.cross(e2).norm(), e1.dot(e2)) * n.normalized();
        }
    }
    for (std::size_t k = 0; k < 3 * nt; ++k) {
        const Eigen::Vector3d& n = sum[corners.root(static_cast<int>(k))];
        if (n.norm() == 0)
            // Bad input, not our failure: the mesh folds back on itself at this vertex.
            throw geom::InvalidInput("pn_triangles: vertex " + std::to_string(m.triangles[k / 3][k % 3]) +
                                     " has no normal (its triangles cancel or are degenerate)");
        out.normal[k] = n.normalized();
    }
    return out;
}

}  // namespace

TbpSolid pn_triangles(const mesh::Mesh& input, double sharp_angle, const VertexPairs& sharp_edges) {
    if (!(sharp_angle >= 0.0))
        throw geom::InvalidInput("pn_triangles: sharp_angle = " + geom::format_value(sharp_angle) + "; expected >= 0");
    const auto vertices = static_cast<std::int32_t>(input.positions.size());
    for (std::size_t k = 0; k < sharp_edges.size(); ++k) {
        const auto [a, b] = sharp_edges[k];
        if (a < 0 || b < 0 || a >= vertices || b >= vertices)
            throw geom::InvalidInput("pn_triangles: sharp_edges[" + std::to_string(k) + "] = (" + std::to_string(a) +
                                     ", " + std::to_string(b) + "); expected vertex indices in [0, " +
                                     std::to_string(vertices) + ")");
    }
    std::vector<std::int32_t> map;
    const mesh::Mesh m = welded_cage(input, "pn_triangles", &map);
    SidePairs marked;
    marked.reserve(sharp_edges.size());
    for (const auto& [a, b] : sharp_edges) {
        const std::int32_t wa = map[a], wb = map[b];
        if (wa != wb) marked.emplace_back(std::min(wa, wb), std::max(wa, wb));
    }
    std::sort(marked.begin(), marked.end());
    const CornerNormals normals = corner_normals(m, sharp_angle, marked);
    TbpSolid solid;
    solid.name = "pn";
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
        const auto& tri = m.triangles[t];
        const Eigen::Vector3d P[3] = {m.positions[tri[0]], m.positions[tri[1]], m.positions[tri[2]]};
        const Eigen::Vector3d* n = &normals.normal[3 * t];
        // [VPBM01] Sec. 3.1: edge point near Pi towards Pj: (2 Pi + Pj - w_ij Ni) / 3,
        // w_ij = (Pj - Pi) . Ni; on a sharp side the straight line's (w_ij = 0), which
        // both triangles of the side share: the crease stays, the solid stays closed.
        const auto& sharp = normals.sharp_side[t];
        auto edge = [&](int i, int j) {
            const bool crease = sharp[(j == (i + 1) % 3) ? i : j];
            return crease ? Eigen::Vector3d((2 * P[i] + P[j]) / 3.0)
                          : Eigen::Vector3d((2 * P[i] + P[j] - (P[j] - P[i]).dot(n[i]) * n[i]) / 3.0);
        };
        const Eigen::Vector3d b210 = edge(0, 1), b120 = edge(1, 0), b021 = edge(1, 2), b012 = edge(2, 1),
                              b102 = edge(2, 0), b201 = edge(0, 2);
        // Centre b111 = E + (E - V) / 2.
        const Eigen::Vector3d E = (b210 + b120 + b021 + b012 + b102 + b201) / 6.0;
        const Eigen::Vector3d V = (P[0] + P[1] + P[2]) / 3.0;
        const Eigen::Vector3d b111 = E + (E - V) / 2.0;
        // storage order b300 b210 b201 b120 b111 b102 b030 b021 b012 b003
        solid.patches.emplace_back(3, std::vector<Eigen::Vector3d>{P[0], b210, b201, b120, b111, b102, P[1], b021, b012, P[2]});
    }
    return solid;
}

namespace {

// Relative distance below which a quartic patch counts as the exact limit surface.
constexpr double kExactRelativeTolerance = 1e-9;

}  // namespace

LoopConversion loop_quartics(const mesh::Mesh& input) {
#ifndef TRIMKIT_HAVE_OPENSUBDIV
    (void)input;
    throw geom::NumericalFailure("loop_quartics: trimkit was built without OpenSubdiv");
#else
    using namespace OpenSubdiv;
    const mesh::Mesh m = welded_cage(input, "loop_quartics");
    const int n = 4, count = geom::BezierTriangle::point_count(n);
    std::vector<int> sizes(m.triangles.size(), 3);
    std::vector<int> indices;
    for (const auto& t : m.triangles) indices.insert(indices.end(), t.begin(), t.end());
    Far::TopologyDescriptor desc;
    desc.numVertices = static_cast<int>(m.positions.size());
    desc.numFaces = static_cast<int>(m.triangles.size());
    desc.numVertsPerFace = sizes.data();
    desc.vertIndicesPerFace = indices.data();
    Sdc::Options sdc;
    sdc.SetVtxBoundaryInterpolation(Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
    std::unique_ptr<Far::TopologyRefiner> refiner(Far::TopologyRefinerFactory<Far::TopologyDescriptor>::Create(
        desc, Far::TopologyRefinerFactory<Far::TopologyDescriptor>::Options(Sdc::SCHEME_LOOP, sdc)));
    if (!refiner) throw geom::NumericalFailure("loop_quartics: OpenSubdiv rejected the cage topology");
    Bfr::RefinerSurfaceFactory<> factory(*refiner);

    // Interpolation at the domain points (i,j,k)/n, Bernstein matrix inverted once.
    std::vector<Eigen::Vector3d> nodes(count);
    for (int i = n; i >= 0; --i)
        for (int j = n - i; j >= 0; --j) nodes[geom::BezierTriangle::index(n, i, j)] = Eigen::Vector3d(i, j, n - i - j) / n;
    Eigen::MatrixXd B(count, count);
    for (int r = 0; r < count; ++r)
        for (int i = n; i >= 0; --i)
            for (int j = n - i; j >= 0; --j) {
                const int k = n - i - j;
                double f = 1;  // n! / (i! j! k!)
                for (int q = 2; q <= n; ++q) f *= q;
                for (int q = 2; q <= i; ++q) f /= q;
                for (int q = 2; q <= j; ++q) f /= q;
                for (int q = 2; q <= k; ++q) f /= q;
                B(r, geom::BezierTriangle::index(n, i, j)) =
                    f * std::pow(nodes[r][0], i) * std::pow(nodes[r][1], j) * std::pow(nodes[r][2], k);
            }
    const Eigen::MatrixXd Binv = B.inverse();
    const DomainPattern check = triangle_pattern(8);

    LoopConversion out;
    out.solid.name = "loop";
    const double scale = mesh::bounding_box(m).diagonal().norm();
    Bfr::Surface<double> surface;
    const Bfr::Surface<double>::PointDescriptor desc3(3);
    std::vector<double> patch_points;
    auto limit = [&](const Eigen::Vector3d& uvw) {
        // Bfr's triangle: corners 0 (0,0), 1 (1,0), 2 (0,1); (u,v,w) = (1-s-t, s, t).
        const double st[2] = {uvw[1], uvw[2]};
        Eigen::Vector3d P;
        surface.Evaluate(st, patch_points.data(), desc3, P.data());
        return P;
    };
    for (int f = 0; f < desc.numFaces; ++f) {
        if (!factory.InitVertexSurface(f, &surface) || !surface.IsValid())
            throw geom::NumericalFailure("loop_quartics: no limit surface for face " + std::to_string(f));
        patch_points.resize(3 * static_cast<std::size_t>(surface.GetNumPatchPoints()));
        surface.PreparePatchPoints(m.positions[0].data(), desc3, patch_points.data(), desc3);
        Eigen::MatrixXd values(count, 3);
        for (int r = 0; r < count; ++r) values.row(r) = limit(nodes[r]).transpose();
        const Eigen::MatrixXd C = Binv * values;
        std::vector<Eigen::Vector3d> points(count);
        for (int r = 0; r < count; ++r) points[r] = C.row(r).transpose();
        geom::BezierTriangle patch(n, std::move(points));
        double error = 0;
        for (const Eigen::Vector3d& t : check.points) error = std::max(error, (patch.evaluate(t) - limit(t)).norm());
        if (error > kExactRelativeTolerance * scale) ++out.approximated;
        out.max_error = std::max(out.max_error, error);
        out.solid.patches.push_back(std::move(patch));
    }
    return out;
#endif
}

}  // namespace trimkit::tbp
