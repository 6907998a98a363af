// PLY reader (binary_little_endian and ascii, format 1.0): the vertex element's
// x y z [nx ny nz] [u v | s t | texture_u texture_v] and the face element's
// vertex_indices (or vertex_index) list [face_id]; other elements and
// properties are skipped. Polygons are fanned into triangles.
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

#include "geom/error.h"
#include "io/read_mesh.h"
#include "io/read_support.h"

namespace trimkit::io {
namespace {

enum class Type { kI8, kU8, kI16, kU16, kI32, kU32, kF32, kF64 };

struct Property {
    std::string name;
    Type type = Type::kF32;
    bool list = false;
    Type count_type = Type::kU8;
};

struct Element {
    std::string name;
    std::uint64_t count = 0;
    std::vector<Property> properties;
    int line = 0;
};

std::size_t type_size(Type t) {
    switch (t) {
        case Type::kI8: case Type::kU8: return 1;
        case Type::kI16: case Type::kU16: return 2;
        case Type::kI32: case Type::kU32: case Type::kF32: return 4;
        case Type::kF64: return 8;
    }
    return 0;
}

bool parse_type(const std::string& s, Type& t) {
    if (s == "char" || s == "int8") t = Type::kI8;
    else if (s == "uchar" || s == "uint8") t = Type::kU8;
    else if (s == "short" || s == "int16") t = Type::kI16;
    else if (s == "ushort" || s == "uint16") t = Type::kU16;
    else if (s == "int" || s == "int32") t = Type::kI32;
    else if (s == "uint" || s == "uint32") t = Type::kU32;
    else if (s == "float" || s == "float32") t = Type::kF32;
    else if (s == "double" || s == "float64") t = Type::kF64;
    else return false;
    return true;
}

// Values of the body, one at a time, in binary or ascii.
class ValueReader {
public:
    ValueReader(const std::string& bytes, std::size_t begin, bool ascii, int first_line,
                const std::string& file)
        : bytes_(bytes), cursor_(bytes, begin, bytes.size(), file), ascii_(ascii), pos_(begin),
          line_(first_line), file_(file) {}

    double next(Type t) {
        if (!ascii_) {
            switch (t) {
                case Type::kI8: return static_cast<std::int8_t>(cursor_.u8("a PLY value"));
                case Type::kU8: return cursor_.u8("a PLY value");
                case Type::kI16: return static_cast<std::int16_t>(cursor_.u16("a PLY value"));
                case Type::kU16: return cursor_.u16("a PLY value");
                case Type::kI32: return cursor_.i32("a PLY value");
                case Type::kU32: return cursor_.u32("a PLY value");
                case Type::kF32: return cursor_.f32("a PLY value");
                case Type::kF64: return cursor_.f64("a PLY value");
            }
        }
        while (pos_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[pos_]))) {
            if (bytes_[pos_] == '\n') ++line_;
            ++pos_;
        }
        if (pos_ >= bytes_.size()) throw geom::ReadError(file_, line_, "truncated: expected a value");
        std::size_t end = pos_;
        while (end < bytes_.size() && !std::isspace(static_cast<unsigned char>(bytes_[end]))) ++end;
        const std::string token = bytes_.substr(pos_, std::min<std::size_t>(end - pos_, 64));
        char* stop = nullptr;
        const double x = std::strtod(token.c_str(), &stop);
        if (stop == token.c_str() || *stop != '\0')
            throw geom::ReadError(file_, line_, "'" + token + "' is not a number");
        pos_ = end;
        return x;
    }

    std::size_t remaining() const { return ascii_ ? bytes_.size() - pos_ : cursor_.remaining(); }
    int line() const { return ascii_ ? line_ : 0; }

private:
    const std::string& bytes_;
    ByteCursor cursor_;
    bool ascii_;
    std::size_t pos_;
    int line_;
    const std::string& file_;
};

}  // namespace

mesh::Mesh read_ply(const std::string& path) { return parse_ply(read_file_bytes(path), path); }

mesh::Mesh parse_ply(const std::string& bytes, const std::string& path) {
    if (bytes.compare(0, 4, "ply\n") != 0 && bytes.compare(0, 5, "ply\r\n") != 0)
        throw geom::ReadError(path, 1, "not a PLY file (no 'ply' magic line)");
    const std::size_t header_end = bytes.find("end_header");
    if (header_end == std::string::npos)
        throw geom::ReadError(path, 0, "PLY header has no 'end_header'");
    std::size_t body = bytes.find('\n', header_end);
    if (body == std::string::npos) throw geom::ReadError(path, 0, "truncated after 'end_header'");
    ++body;

    // ---- Header ----
    std::istringstream header(bytes.substr(0, header_end));
    std::string line_text;
    int line = 0;
    bool ascii = false, have_format = false;
    std::vector<Element> elements;
    while (std::getline(header, line_text)) {
        ++line;
        if (!line_text.empty() && line_text.back() == '\r') line_text.pop_back();
        std::istringstream words(line_text);
        std::string keyword;
        words >> keyword;
        if (keyword.empty() || keyword == "ply" || keyword == "comment" || keyword == "obj_info") continue;
        if (keyword == "format") {
            std::string format, version;
            words >> format >> version;
            if (format == "ascii") ascii = true;
            else if (format != "binary_little_endian")
                throw geom::ReadError(path, line, "PLY format '" + format +
                                                      "' unsupported; expected binary_little_endian or ascii");
            have_format = true;
        } else if (keyword == "element") {
            Element e;
            std::string count;
            words >> e.name >> count;
            char* stop = nullptr;
            const double n = std::strtod(count.c_str(), &stop);
            if (count.empty() || *stop != '\0' || !(n >= 0) || n != std::floor(n) || n > 1e15)
                throw geom::ReadError(path, line, "element '" + e.name + "' count '" + count +
                                                      "' is not a non-negative integer");
            e.count = static_cast<std::uint64_t>(n);
            e.line = line;
            elements.push_back(e);
        } else if (keyword == "property") {
            if (elements.empty()) throw geom::ReadError(path, line, "property before any element");
            Property p;
            std::string type;
            words >> type;
            if (type == "list") {
                std::string count_type, item_type;
                words >> count_type >> item_type >> p.name;
                p.list = true;
                if (!parse_type(count_type, p.count_type) || !parse_type(item_type, p.type) ||
                    p.count_type == Type::kF32 || p.count_type == Type::kF64)
                    throw geom::ReadError(path, line, "bad list property types '" + count_type +
                                                          " " + item_type + "'");
            } else {
                words >> p.name;
                if (!parse_type(type, p.type))
                    throw geom::ReadError(path, line, "unknown property type '" + type + "'");
            }
            elements.back().properties.push_back(p);
        } else {
            throw geom::ReadError(path, line, "unknown PLY header keyword '" + keyword + "'");
        }
    }
    if (!have_format) throw geom::ReadError(path, 0, "PLY header has no 'format' line");

    // ---- Body ----
    mesh::Mesh mesh;
    ValueReader in(bytes, body, ascii, line + 2, path);
    bool have_vertices = false;
    for (const Element& e : elements) {
        // Smallest size of one instance, to refuse counts the file cannot hold.
        std::size_t min_size = 0;
        for (const Property& p : e.properties)
            min_size += ascii ? 2 : type_size(p.list ? p.count_type : p.type);
        if (min_size == 0) min_size = 1;
        if (e.count > in.remaining() / min_size)
            throw geom::ReadError(path, e.line, "element '" + e.name + "' claims " +
                                                    std::to_string(e.count) + " entries; the file holds at most " +
                                                    std::to_string(in.remaining() / min_size));
        if (e.name == "vertex") {
            int ix = -1, iy = -1, iz = -1, inx = -1, iny = -1, inz = -1, iu = -1, iv = -1;
            for (int k = 0; k < static_cast<int>(e.properties.size()); ++k) {
                const std::string& n = e.properties[k].name;
                if (e.properties[k].list) continue;
                if (n == "x") ix = k;
                else if (n == "y") iy = k;
                else if (n == "z") iz = k;
                else if (n == "nx") inx = k;
                else if (n == "ny") iny = k;
                else if (n == "nz") inz = k;
                else if (n == "u" || n == "s" || n == "texture_u") iu = k;
                else if (n == "v" || n == "t" || n == "texture_v") iv = k;
            }
            if (ix < 0 || iy < 0 || iz < 0)
                throw geom::ReadError(path, e.line, "vertex element lacks x, y or z");
            const bool normals = inx >= 0 && iny >= 0 && inz >= 0, uvs = iu >= 0 && iv >= 0;
            const std::size_t n = static_cast<std::size_t>(e.count);
            mesh.positions.resize(n);
            if (normals) mesh.normals.resize(n);
            if (uvs) mesh.uvs.resize(n);
            std::vector<double> values(e.properties.size());
            for (std::size_t i = 0; i < n; ++i) {
                for (std::size_t k = 0; k < e.properties.size(); ++k) {
                    const Property& p = e.properties[k];
                    if (p.list) {
                        const double count = in.next(p.count_type);
                        if (!(count >= 0) || count > static_cast<double>(in.remaining()))
                            throw geom::ReadError(path, in.line(), "bad list length in vertex " + std::to_string(i));
                        for (int c = 0; c < static_cast<int>(count); ++c) in.next(p.type);
                    } else {
                        values[k] = in.next(p.type);
                    }
                }
                mesh.positions[i] = {values[ix], values[iy], values[iz]};
                if (normals) mesh.normals[i] = {values[inx], values[iny], values[inz]};
                if (uvs) mesh.uvs[i] = {values[iu], values[iv]};
            }
            have_vertices = true;
        } else if (e.name == "face") {
            int indices = -1, face_id = -1;
            for (int k = 0; k < static_cast<int>(e.properties.size()); ++k) {
                const Property& p = e.properties[k];
                if (p.list && (p.name == "vertex_indices" || p.name == "vertex_index")) indices = k;
                else if (!p.list && p.name == "face_id") face_id = k;
            }
            if (indices < 0) throw geom::ReadError(path, e.line, "face element lacks vertex_indices");
            if (!have_vertices) throw geom::ReadError(path, e.line, "face element before the vertex element");
            mesh.triangles.reserve(static_cast<std::size_t>(e.count));
            const double nv = static_cast<double>(mesh.positions.size());
            std::vector<std::int32_t> polygon;
            for (std::uint64_t f = 0; f < e.count; ++f) {
                polygon.clear();
                double id = 0;
                for (std::size_t k = 0; k < e.properties.size(); ++k) {
                    const Property& p = e.properties[k];
                    if (p.list) {
                        const double count = in.next(p.count_type);
                        if (!(count >= 0) || count > static_cast<double>(in.remaining()))
                            throw geom::ReadError(path, in.line(), "face " + std::to_string(f) +
                                                                       ": bad list length " + std::to_string(count));
                        for (int c = 0; c < static_cast<int>(count); ++c) {
                            const double x = in.next(p.type);
                            if (static_cast<int>(k) == indices) {
                                if (!(x >= 0 && x < nv) || x != std::floor(x))
                                    throw geom::ReadError(path, in.line(), "face " + std::to_string(f) +
                                        ": vertex index " + geom::format_value(x) + " out of range [0, " +
                                        std::to_string(mesh.positions.size()) + ")");
                                polygon.push_back(static_cast<std::int32_t>(x));
                            }
                        }
                    } else {
                        const double x = in.next(p.type);
                        if (static_cast<int>(k) == face_id) id = x;
                    }
                }
                if (polygon.size() < 3)
                    throw geom::ReadError(path, in.line(), "face " + std::to_string(f) + " has " +
                                                               std::to_string(polygon.size()) + " vertices, expected >= 3");
                if (face_id >= 0 && (!(id >= 0 && id <= std::numeric_limits<std::int32_t>::max()) || id != std::floor(id)))
                    throw geom::ReadError(path, in.line(), "face " + std::to_string(f) + ": face_id " +
                                                               geom::format_value(id) + " is not an index >= 0");
                for (std::size_t c = 1; c + 1 < polygon.size(); ++c) {
                    mesh.triangles.push_back({polygon[0], polygon[c], polygon[c + 1]});
                    if (face_id >= 0) mesh.face_ids.push_back(static_cast<std::int32_t>(id));
                }
            }
        } else {
            for (std::uint64_t i = 0; i < e.count; ++i)
                for (const Property& p : e.properties) {
                    if (p.list) {
                        const double count = in.next(p.count_type);
                        if (!(count >= 0) || count > static_cast<double>(in.remaining()))
                            throw geom::ReadError(path, in.line(), "bad list length in element '" + e.name + "'");
                        for (int c = 0; c < static_cast<int>(count); ++c) in.next(p.type);
                    } else {
                        in.next(p.type);
                    }
                }
        }
    }
    if (!have_vertices) throw geom::ReadError(path, 0, "PLY file has no vertex element");
    finish_read_mesh(mesh, path);
    return mesh;
}

}  // namespace trimkit::io
