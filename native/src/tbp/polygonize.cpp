#include "tbp/polygonize.h"

#include <cmath>
#include <map>
#include <string>

#include "geom/error.h"
#include "mesh/weld_vertices.h"

#ifdef TRIMKIT_HAVE_OPENSUBDIV
#include <opensubdiv/bfr/parameterization.h>
#include <opensubdiv/bfr/tessellation.h>
#endif

namespace trimkit::tbp {

int polygonize_rate(int level, int lod) {
    if (level < 0 || lod < 0)
        throw geom::InvalidInput("polygonize: level " + std::to_string(level) + ", lod " + std::to_string(lod) +
                                 "; both must be >= 0");
    long long rate = 1;
    for (int l = 0; l < level; ++l) {
        rate *= lod + 1;
        if (rate > kMaxPolygonizeRate)
            throw geom::InvalidInput("polygonize: level " + std::to_string(level) + " and lod " + std::to_string(lod) +
                                     " give more than " + std::to_string(kMaxPolygonizeRate) + " segments per edge");
    }
    return static_cast<int>(rate);
}

DomainPattern triangle_pattern(int rate) {
    if (rate < 1 || rate > kMaxPolygonizeRate)
        throw geom::InvalidInput("triangle_pattern: rate " + std::to_string(rate) + "; expected 1 to " +
                                 std::to_string(kMaxPolygonizeRate));
    DomainPattern out;
#ifdef TRIMKIT_HAVE_OPENSUBDIV
    using namespace OpenSubdiv;
    const Bfr::Parameterization param(Sdc::SCHEME_LOOP, 3);
    const Bfr::Tessellation tess(param, rate);
    if (!tess.IsValid()) throw geom::NumericalFailure("triangle_pattern: Bfr::Tessellation rejected rate " + std::to_string(rate));
    std::vector<double> st(2 * static_cast<std::size_t>(tess.GetNumCoords()));
    tess.GetCoords(st.data());
    // Bfr's triangle has corners 0 (0,0), 1 (1,0), 2 (0,1) and lists the boundary
    // (corners first) before the interior. Corner 0 -> u, 1 -> v, 2 -> w:
    // (u, v, w) = (1-s-t, s, t), an orientation-preserving map of the (s,t) plane.
    // Coordinates are snapped to the exact multiples of 1/rate they stand for, so
    // both patches of a shared edge evaluate at bit-identical parameters.
    out.points.reserve(st.size() / 2);
    for (std::size_t q = 0; q < st.size(); q += 2) {
        const double s = std::round(st[q] * rate), t = std::round(st[q + 1] * rate);
        out.points.emplace_back((rate - s - t) / rate, s / rate, t / rate);
    }
    std::vector<int> facets(3 * static_cast<std::size_t>(tess.GetNumFacets()));
    tess.GetFacets(facets.data());
    for (std::size_t f = 0; f < facets.size(); f += 3) out.triangles.push_back({facets[f], facets[f + 1], facets[f + 2]});
#else
    // Uniform pattern of our own, same points and the same up/down triangles.
    std::map<std::pair<int, int>, int> id;
    auto point = [&](int a, int b) {
        auto it = id.find({a, b});
        if (it != id.end()) return it->second;
        out.points.emplace_back(double(a) / rate, double(b) / rate, double(rate - a - b) / rate);
        return id[{a, b}] = static_cast<int>(out.points.size()) - 1;
    };
    for (int a = rate; a > 0; --a) point(a, rate - a);  // boundary: u -> v -> w -> u
    for (int b = rate; b > 0; --b) point(0, b);
    for (int a = 0; a < rate; ++a) point(a, 0);
    for (int b = 0; b < rate; ++b)
        for (int a = 0; a + b < rate; ++a) {
            out.triangles.push_back({point(a + 1, b), point(a, b + 1), point(a, b)});
            if (a + b + 2 <= rate) out.triangles.push_back({point(a, b + 1), point(a + 1, b), point(a + 1, b + 1)});
        }
#endif
    return out;
}

mesh::Mesh polygonize_patch(const TbpPatch& patch, int rate, int face_id) {
    const DomainPattern pattern = triangle_pattern(rate);
    mesh::Mesh m;
    m.positions.reserve(pattern.points.size());
    for (const Eigen::Vector3d& t : pattern.points) {
        m.positions.push_back(patch.evaluate(t));
        m.normals.push_back(patch.normal(t));
        m.uvs.emplace_back(t[0], t[1]);
    }
    for (const auto& tri : pattern.triangles) m.triangles.push_back({tri[0], tri[1], tri[2]});
    m.face_ids.assign(m.triangles.size(), face_id);
    return m;
}

mesh::Mesh polygonize(const TbpSolid& solid, const PolygonizeOptions& options) {
    validate(solid);
    const int rate = polygonize_rate(options.level, options.lod);
    mesh::Mesh out;
    Eigen::AlignedBox3d box;
    for (std::size_t p = 0; p < solid.patches.size(); ++p) {
        try {
            mesh::append(out, polygonize_patch(solid.patches[p], rate, static_cast<int>(p)));
        } catch (const geom::NumericalFailure& e) {
            // No normal even a little way inside (BezierTriangle::normal): the patch
            // has no area there, a defect of the solid, so bad input naming the patch.
            throw geom::InvalidInput("polygonize: patch " + std::to_string(p) + " is degenerate: " + e.what());
        }
        box.extend(solid.patches[p].bounding_box());
    }
    if (options.weld) {
        mesh::WeldOptions weld;
        weld.tolerance = kWeldRelativeTolerance * box.diagonal().norm();
        weld.keep_split_normals = options.keep_split_normals;
        mesh::weld_vertices(out, weld);
    }
    return out;
}

}  // namespace trimkit::tbp
