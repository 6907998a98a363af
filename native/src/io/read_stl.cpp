// STL reader: binary (80-byte header, uint32 count, 50 bytes per triangle;
// recognised by the size matching the count) or ascii (solid / facet / vertex).
// Corners with exactly equal coordinates share one vertex, numbered by first
// use; stored facet normals are ignored (the mesh gets no normals).
#include <cmath>
#include <cstdlib>
#include <map>

#include "geom/error.h"
#include "io/read_mesh.h"
#include "io/read_support.h"

namespace trimkit::io {
namespace {

struct LessPoint {
    bool operator()(const Eigen::Vector3d& a, const Eigen::Vector3d& b) const {
        return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
    }
};

class CornerIndex {
public:
    explicit CornerIndex(mesh::Mesh& mesh) : mesh_(mesh) {}
    std::int32_t operator()(const Eigen::Vector3d& p) {
        auto [it, added] = index_.emplace(p, static_cast<std::int32_t>(mesh_.positions.size()));
        if (added) mesh_.positions.push_back(p);
        return it->second;
    }

private:
    mesh::Mesh& mesh_;
    std::map<Eigen::Vector3d, std::int32_t, LessPoint> index_;
};

void read_binary(const std::string& bytes, const std::string& path, mesh::Mesh& mesh) {
    ByteCursor in(bytes, 0, bytes.size(), path);
    in.skip(80, "the STL header");
    const std::uint32_t count = in.u32("the triangle count");
    if (count > in.remaining() / 50)
        throw geom::ReadError(path, 0, "binary STL claims " + std::to_string(count) +
                                           " triangles; the file holds " + std::to_string(in.remaining() / 50));
    CornerIndex index(mesh);
    mesh.triangles.reserve(count);
    for (std::uint32_t t = 0; t < count; ++t) {
        in.skip(12, "a facet normal");
        std::array<std::int32_t, 3> tri;
        for (int k = 0; k < 3; ++k) {
            Eigen::Vector3d p;
            for (int c = 0; c < 3; ++c) p[c] = in.f32("a vertex");
            if (!p.allFinite())
                throw geom::ReadError(path, 0, "triangle " + std::to_string(t) + " has a non-finite vertex");
            tri[k] = index(p);
        }
        in.skip(2, "the attribute byte count");
        mesh.triangles.push_back(tri);
    }
}

void read_ascii(const std::string& bytes, const std::string& path, mesh::Mesh& mesh) {
    CornerIndex index(mesh);
    std::size_t pos = 0;
    int line = 1;
    auto word = [&](std::string& w) {
        while (pos < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[pos]))) {
            if (bytes[pos] == '\n') ++line;
            ++pos;
        }
        if (pos >= bytes.size()) return false;
        const std::size_t start = pos;
        while (pos < bytes.size() && !std::isspace(static_cast<unsigned char>(bytes[pos]))) ++pos;
        w.assign(bytes, start, std::min<std::size_t>(pos - start, 256));
        return true;
    };
    std::string w;
    if (!word(w) || w != "solid") throw geom::ReadError(path, line, "ascii STL does not start with 'solid'");
    std::array<std::int32_t, 3> tri{};
    int corner = 0;
    bool ended = false;
    while (word(w)) {
        if (w == "vertex") {
            Eigen::Vector3d p;
            for (int c = 0; c < 3; ++c) {
                std::string x;
                if (!word(x)) throw geom::ReadError(path, line, "truncated vertex");
                char* stop = nullptr;
                p[c] = std::strtod(x.c_str(), &stop);
                if (stop == x.c_str() || *stop != '\0' || !std::isfinite(p[c]))
                    throw geom::ReadError(path, line, "vertex coordinate '" + x + "' is not a finite number");
            }
            if (corner >= 3) throw geom::ReadError(path, line, "facet has more than 3 vertices");
            tri[corner++] = index(p);
        } else if (w == "endloop") {
            if (corner != 3)
                throw geom::ReadError(path, line, "facet has " + std::to_string(corner) + " vertices, expected 3");
            mesh.triangles.push_back(tri);
            corner = 0;
        } else if (w == "endsolid") {
            ended = true;
            break;
        }
    }
    if (!ended) throw geom::ReadError(path, line, "truncated ascii STL: no 'endsolid'");
}

}  // namespace

mesh::Mesh read_stl(const std::string& path) { return parse_stl(read_file_bytes(path), path); }

mesh::Mesh parse_stl(const std::string& bytes, const std::string& path) {
    mesh::Mesh mesh;
    bool binary = true;
    if (bytes.size() >= 84) {
        ByteCursor in(bytes, 80, 84, path);
        const std::uint64_t count = in.u32("the triangle count");
        binary = 84 + 50 * count == bytes.size() || bytes.compare(0, 5, "solid") != 0;
    } else {
        binary = bytes.compare(0, 5, "solid") != 0;
    }
    if (binary) read_binary(bytes, path, mesh);
    else read_ascii(bytes, path, mesh);
    finish_read_mesh(mesh, path);
    return mesh;
}

}  // namespace trimkit::io
