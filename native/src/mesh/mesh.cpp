#include "mesh/mesh.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>

#include "geom/error.h"

namespace trimkit::mesh {
namespace {

using geom::format_value;
using geom::InvalidInput;

template <class Vector>
std::string format_vector(const Vector& v) {
    std::string text = "(";
    for (Eigen::Index k = 0; k < v.size(); ++k) {
        if (k > 0) text += ", ";
        text += format_value(static_cast<double>(v[k]));
    }
    return text + ")";
}

[[noreturn]] void fail(const std::string& what) { throw InvalidInput("Mesh: " + what); }

void check_size(std::size_t size, std::size_t expected, const char* array, const char* per) {
    if (size != 0 && size != expected) {
        std::ostringstream out;
        out << array << " has " << size << " entries; expected 0 or " << expected << " (one per "
            << per << ")";
        fail(out.str());
    }
}

}  // namespace

void validate(const Mesh& mesh) {
    const std::size_t nv = mesh.positions.size();
    const std::size_t nt = mesh.triangles.size();
    check_size(mesh.normals.size(), nv, "normals", "vertex");
    check_size(mesh.uvs.size(), nv, "uvs", "vertex");
    check_size(mesh.face_ids.size(), nt, "face_ids", "triangle");

    for (std::size_t i = 0; i < nv; ++i) {
        if (!mesh.positions[i].allFinite())
            fail("positions[" + std::to_string(i) + "] = " + format_vector(mesh.positions[i]) +
                 "; coordinates must be finite");
    }
    for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
        const Eigen::Vector3d& n = mesh.normals[i];
        if (!n.allFinite() || std::abs(n.norm() - 1.0) > kUnitNormalTolerance)
            fail("normals[" + std::to_string(i) + "] = " + format_vector(n) + " has length " +
                 format_value(n.norm()) + "; normals must be finite and of unit length");
    }
    for (std::size_t i = 0; i < mesh.uvs.size(); ++i) {
        if (!mesh.uvs[i].allFinite())
            fail("uvs[" + std::to_string(i) + "] = " + format_vector(mesh.uvs[i]) +
                 "; parameters must be finite");
    }
    for (std::size_t t = 0; t < nt; ++t) {
        for (int k = 0; k < 3; ++k) {
            const std::int32_t v = mesh.triangles[t][k];
            if (v < 0 || static_cast<std::size_t>(v) >= nv)
                fail("triangles[" + std::to_string(t) + "][" + std::to_string(k) + "] = " +
                     std::to_string(v) + "; expected a vertex index in [0, " +
                     std::to_string(nv) + ")");
        }
    }
    for (std::size_t t = 0; t < mesh.face_ids.size(); ++t) {
        const std::int32_t id = mesh.face_ids[t];
        if (id < 0)
            fail("face_ids[" + std::to_string(t) + "] = " + std::to_string(id) +
                 "; face ids must be >= 0");
        if (!mesh.face_colors.empty() && static_cast<std::size_t>(id) >= mesh.face_colors.size())
            fail("face_ids[" + std::to_string(t) + "] = " + std::to_string(id) +
                 " has no colour; face_colors has " + std::to_string(mesh.face_colors.size()) +
                 " entries");
    }
    for (std::size_t f = 0; f < mesh.face_colors.size(); ++f) {
        for (int k = 0; k < 3; ++k) {
            const float c = mesh.face_colors[f][k];
            if (!(c >= 0.0f && c <= 1.0f))
                fail("face_colors[" + std::to_string(f) + "][" + std::to_string(k) + "] = " +
                     format_value(c) + "; colour components must be in [0, 1]");
        }
    }
    std::vector<std::pair<std::int32_t, std::int32_t>> pairs;
    pairs.reserve(mesh.edges.size());
    for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
        const FlaggedEdge& edge = mesh.edges[e];
        const std::string name = "edges[" + std::to_string(e) + "]";
        for (std::int32_t v : {edge.v0, edge.v1}) {
            if (v < 0 || static_cast<std::size_t>(v) >= nv)
                fail(name + " uses vertex " + std::to_string(v) + "; expected an index in [0, " +
                     std::to_string(nv) + ")");
        }
        if (edge.v0 == edge.v1)
            fail(name + " joins vertex " + std::to_string(edge.v0) + " to itself");
        if (edge.flags == 0 || (edge.flags & ~(kFaceBoundary | kSharp)) != 0)
            fail(name + " has flags " + std::to_string(edge.flags) +
                 "; expected a non-zero combination of kFaceBoundary (1) and kSharp (2)");
        pairs.emplace_back(std::min(edge.v0, edge.v1), std::max(edge.v0, edge.v1));
    }
    std::sort(pairs.begin(), pairs.end());
    const auto repeat = std::adjacent_find(pairs.begin(), pairs.end());
    if (repeat != pairs.end())
        fail("edge (" + std::to_string(repeat->first) + ", " + std::to_string(repeat->second) +
             ") is listed more than once in edges");
}

void append(Mesh& into, const Mesh& part) {
    const bool into_empty = into.positions.empty() && into.triangles.empty();
    const bool part_empty = part.positions.empty() && part.triangles.empty();
    if (!into_empty && !part_empty) {
        auto require_same = [](bool a, bool b, const char* array) {
            if (a != b)
                throw InvalidInput(std::string("append: ") + (a ? "into" : "part") + " has " +
                                   array + " but " + (a ? "part" : "into") +
                                   " has none; both meshes must carry the same arrays");
        };
        require_same(into.has_normals(), part.has_normals(), "normals");
        require_same(into.has_uvs(), part.has_uvs(), "uvs");
        require_same(into.has_face_ids(), part.has_face_ids(), "face_ids");
    }
    if (into.positions.size() + part.positions.size() >
        static_cast<std::size_t>(INT32_MAX))
        throw InvalidInput("append: " + std::to_string(into.positions.size()) + " + " +
                           std::to_string(part.positions.size()) +
                           " vertices exceed the int32 index range");

    if (!part_empty) {
        const auto offset = static_cast<std::int32_t>(into.positions.size());
        into.positions.insert(into.positions.end(), part.positions.begin(), part.positions.end());
        into.normals.insert(into.normals.end(), part.normals.begin(), part.normals.end());
        into.uvs.insert(into.uvs.end(), part.uvs.begin(), part.uvs.end());
        into.triangles.reserve(into.triangles.size() + part.triangles.size());
        for (const auto& t : part.triangles)
            into.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
        into.face_ids.insert(into.face_ids.end(), part.face_ids.begin(), part.face_ids.end());
        into.edges.reserve(into.edges.size() + part.edges.size());
        for (const auto& e : part.edges)
            into.edges.push_back({e.v0 + offset, e.v1 + offset, e.flags});
    }
    for (std::size_t f = into.face_colors.size(); f < part.face_colors.size(); ++f)
        into.face_colors.push_back(part.face_colors[f]);
}

std::vector<Mesh> split_by_face_group(const Mesh& mesh, const std::vector<int>& group_of_face, int groups) {
    if (!mesh.has_face_ids() && !mesh.triangles.empty())
        throw InvalidInput("split_by_face_group: the mesh has no face ids");
    std::vector<Mesh> parts(std::max(groups, 0));
    std::vector<std::vector<std::size_t>> triangles_of(parts.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const std::int32_t f = mesh.face_ids[t];
        const int g = f >= 0 && static_cast<std::size_t>(f) < group_of_face.size() ? group_of_face[f] : -1;
        if (g >= 0 && g < groups) triangles_of[g].push_back(t);
        else
            throw InvalidInput("split_by_face_group: triangles[" + std::to_string(t) + "] has face id " +
                               std::to_string(f) + ", which has no group in [0, " + std::to_string(groups) + ")");
    }
    // Per vertex: the part that took it last and its index there (a vertex that
    // triangles of several parts use is copied into each).
    std::vector<int> owner(mesh.positions.size(), -1);
    std::vector<std::int32_t> index(mesh.positions.size(), -1);
    for (int g = 0; g < groups; ++g) {
        Mesh& part = parts[g];
        for (std::size_t t : triangles_of[g]) {
            std::array<std::int32_t, 3> corners;
            for (int k = 0; k < 3; ++k) {
                const std::int32_t v = mesh.triangles[t][k];
                if (owner[v] != g) {
                    owner[v] = g;
                    index[v] = static_cast<std::int32_t>(part.positions.size());
                    part.positions.push_back(mesh.positions[v]);
                    if (mesh.has_normals()) part.normals.push_back(mesh.normals[v]);
                    if (mesh.has_uvs()) part.uvs.push_back(mesh.uvs[v]);
                }
                corners[k] = index[v];
            }
            part.triangles.push_back(corners);
            part.face_ids.push_back(mesh.face_ids[t]);
        }
        part.face_colors = mesh.face_colors;
    }
    return parts;
}

double surface_area(const Mesh& mesh) {
    double area = 0.0;
    for (const auto& t : mesh.triangles) {
        const Eigen::Vector3d& a = mesh.positions[t[0]];
        area += 0.5 * (mesh.positions[t[1]] - a).cross(mesh.positions[t[2]] - a).norm();
    }
    return area;
}

Eigen::AlignedBox3d bounding_box(const Mesh& mesh) {
    Eigen::AlignedBox3d box;  // default-constructed: empty
    for (const auto& p : mesh.positions) box.extend(p);
    return box;
}

}  // namespace trimkit::mesh
