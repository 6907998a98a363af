// OBJ reader: v (extra components such as colours ignored), vt, vn, f with
// v, v/vt, v//vn or v/vt/vn corners (1-based, negative = relative to the end),
// polygons fanned; `g face_N` starts the triangles of CAD face N. Other
// statements (o, s, usemtl, mtllib, l, p, ...) are ignored.
#include <cmath>
#include <cstdlib>
#include <limits>
#include <map>
#include <tuple>

#include "geom/error.h"
#include "io/read_mesh.h"
#include "io/read_support.h"

namespace trimkit::io {
namespace {

struct Corner {
    std::int64_t v = -1, vt = -1, vn = -1;  // 0-based, -1 absent
};

class LineParser {
public:
    LineParser(const std::string& bytes, std::size_t begin, std::size_t end, int line,
               const std::string& file)
        : s_(bytes), pos_(begin), end_(end), line_(line), file_(file) {}

    bool next_word(std::string& word) {
        while (pos_ < end_ && (s_[pos_] == ' ' || s_[pos_] == '\t' || s_[pos_] == '\r')) ++pos_;
        if (pos_ >= end_) return false;
        const std::size_t start = pos_;
        while (pos_ < end_ && s_[pos_] != ' ' && s_[pos_] != '\t' && s_[pos_] != '\r') ++pos_;
        word.assign(s_, start, std::min<std::size_t>(pos_ - start, 256));
        return true;
    }

    double number(const char* what) {
        std::string word;
        if (!next_word(word)) throw geom::ReadError(file_, line_, std::string("missing ") + what);
        char* stop = nullptr;
        const double x = std::strtod(word.c_str(), &stop);
        if (stop == word.c_str() || *stop != '\0' || !std::isfinite(x))
            throw geom::ReadError(file_, line_, std::string(what) + " '" + word + "' is not a finite number");
        return x;
    }

private:
    const std::string& s_;
    std::size_t pos_, end_;
    int line_;
    const std::string& file_;
};

// A corner index: 1-based, or negative relative to the `count` entries so far.
std::int64_t resolve(const std::string& text, std::size_t count, const char* what,
                     const std::string& file, int line) {
    char* stop = nullptr;
    const long long i = std::strtoll(text.c_str(), &stop, 10);
    if (text.empty() || *stop != '\0')
        throw geom::ReadError(file, line, std::string(what) + " index '" + text + "' is not an integer");
    const long long n = static_cast<long long>(count);
    const long long k = i > 0 ? i - 1 : n + i;
    if (i == 0 || k < 0 || k >= n)
        throw geom::ReadError(file, line, std::string(what) + " index " + text + " out of range (" +
                                              std::to_string(count) + " defined)");
    return k;
}

}  // namespace

mesh::Mesh read_obj(const std::string& path) { return parse_obj(read_file_bytes(path), path); }

mesh::Mesh parse_obj(const std::string& bytes, const std::string& path) {
    std::vector<Eigen::Vector3d> v, vn;
    std::vector<Eigen::Vector2d> vt;
    std::vector<std::array<Corner, 3>> triangles;
    std::vector<std::int32_t> face_ids;
    std::int64_t group = -1;  // current face id, -1 outside face_N groups
    bool any_group = false;
    int line = 0;
    std::vector<Corner> polygon;
    for (std::size_t pos = 0; pos < bytes.size();) {
        ++line;
        std::size_t end = bytes.find('\n', pos);
        if (end == std::string::npos) end = bytes.size();
        const std::size_t hash = bytes.find('#', pos);
        LineParser words(bytes, pos, hash < end ? hash : end, line, path);
        pos = end + 1;
        std::string keyword;
        if (!words.next_word(keyword)) continue;
        if (keyword == "v") {
            const double x = words.number("x"), y = words.number("y"), z = words.number("z");
            v.emplace_back(x, y, z);
        } else if (keyword == "vt") {
            const double s = words.number("u");
            std::string word;
            double t = 0.0;
            if (words.next_word(word)) {
                char* stop = nullptr;
                t = std::strtod(word.c_str(), &stop);
                if (*stop != '\0' || !std::isfinite(t))
                    throw geom::ReadError(path, line, "v '" + word + "' is not a finite number");
            }
            vt.emplace_back(s, t);
        } else if (keyword == "vn") {
            const double x = words.number("nx"), y = words.number("ny"), z = words.number("nz");
            vn.emplace_back(x, y, z);
        } else if (keyword == "g") {
            std::string name;
            group = -1;
            while (words.next_word(name)) {
                if (name.compare(0, 5, "face_") != 0) continue;
                char* stop = nullptr;
                const long long id = std::strtoll(name.c_str() + 5, &stop, 10);
                if (name.size() > 5 && *stop == '\0' && id >= 0 &&
                    id <= std::numeric_limits<std::int32_t>::max()) {
                    group = id;
                    any_group = true;
                }
            }
        } else if (keyword == "f") {
            polygon.clear();
            std::string word;
            while (words.next_word(word)) {
                Corner c;
                const std::size_t s1 = word.find('/');
                c.v = resolve(word.substr(0, s1), v.size(), "vertex", path, line);
                if (s1 != std::string::npos) {
                    const std::size_t s2 = word.find('/', s1 + 1);
                    const std::string t = word.substr(s1 + 1, s2 == std::string::npos ? std::string::npos : s2 - s1 - 1);
                    if (!t.empty()) c.vt = resolve(t, vt.size(), "texture", path, line);
                    if (s2 != std::string::npos) c.vn = resolve(word.substr(s2 + 1), vn.size(), "normal", path, line);
                }
                polygon.push_back(c);
            }
            if (polygon.size() < 3)
                throw geom::ReadError(path, line, "face has " + std::to_string(polygon.size()) +
                                                      " corners, expected >= 3");
            for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
                triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
                face_ids.push_back(static_cast<std::int32_t>(group));
            }
        }
    }

    // Corners must agree on which attributes they carry for the mesh to hold them.
    bool all_vt = !triangles.empty(), all_vn = !triangles.empty(), same_index = true;
    for (const auto& t : triangles)
        for (const Corner& c : t) {
            all_vt = all_vt && c.vt >= 0;
            all_vn = all_vn && c.vn >= 0;
            same_index = same_index && (c.vt < 0 || c.vt == c.v) && (c.vn < 0 || c.vn == c.v);
        }
    if (any_group)
        for (std::size_t t = 0; t < face_ids.size(); ++t)
            if (face_ids[t] < 0)
                throw geom::ReadError(path, 0, "triangle " + std::to_string(t) +
                                                   " lies outside any 'g face_N' group while others are grouped");

    mesh::Mesh mesh;
    if (same_index && (!all_vt || vt.size() == v.size()) && (!all_vn || vn.size() == v.size())) {
        // The layout trimkit writes: one index for v, vt and vn; keep the numbering.
        mesh.positions = v;
        if (all_vt) mesh.uvs = vt;
        if (all_vn) mesh.normals = vn;
        mesh.triangles.reserve(triangles.size());
        for (const auto& t : triangles)
            mesh.triangles.push_back({static_cast<std::int32_t>(t[0].v), static_cast<std::int32_t>(t[1].v),
                                      static_cast<std::int32_t>(t[2].v)});
    } else {
        // One mesh vertex per distinct (v, vt, vn) corner, numbered by first use.
        std::map<std::tuple<std::int64_t, std::int64_t, std::int64_t>, std::int32_t> index;
        for (const auto& t : triangles) {
            std::array<std::int32_t, 3> tri;
            for (int k = 0; k < 3; ++k) {
                const Corner& c = t[k];
                const auto key = std::make_tuple(c.v, all_vt ? c.vt : -1, all_vn ? c.vn : -1);
                auto [it, added] = index.emplace(key, static_cast<std::int32_t>(mesh.positions.size()));
                if (added) {
                    mesh.positions.push_back(v[c.v]);
                    if (all_vt) mesh.uvs.push_back(vt[c.vt]);
                    if (all_vn) mesh.normals.push_back(vn[c.vn]);
                }
                tri[k] = it->second;
            }
            mesh.triangles.push_back(tri);
        }
    }
    if (any_group) mesh.face_ids = std::move(face_ids);
    if (mesh.positions.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
        throw geom::ReadError(path, 0, "too many vertices");
    finish_read_mesh(mesh, path);
    return mesh;
}

}  // namespace trimkit::io
