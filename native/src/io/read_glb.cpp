// glTF 2.0 binary reader (glTF spec Sec. 4.4 "Binary glTF layout"): the JSON and
// BIN chunks; every primitive of mode 4 (triangles) of every mesh, with POSITION,
// NORMAL and TEXCOORD_0 (float VEC3/VEC3/VEC2) and unsigned indices. Node
// transforms are not applied (trimkit writes none); other modes are refused.
#include <cmath>
#include <limits>

#include "geom/error.h"
#include "io/json_value.h"
#include "io/read_mesh.h"
#include "io/read_support.h"

namespace trimkit::io {
namespace {

constexpr std::uint32_t kGlbMagic = 0x46546C67;   // "glTF"
constexpr std::uint32_t kChunkJson = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;   // "BIN\0"
constexpr int kFloat = 5126, kUnsignedByte = 5121, kUnsignedShort = 5123, kUnsignedInt = 5125;
constexpr int kTriangles = 4;

class Glb {
public:
    Glb(const JsonValue& json, const std::string& bytes, std::size_t bin_begin, std::size_t bin_size,
        const std::string& file)
        : json_(json), bytes_(bytes), bin_begin_(bin_begin), bin_size_(bin_size), file_(file) {}

    [[noreturn]] void fail(const std::string& what) const { throw geom::ReadError(file_, 0, what); }

    // A non-negative integer member (or `fallback` when absent and fallback >= 0).
    std::uint64_t integer(const JsonValue& obj, const std::string& key, const std::string& where,
                          double fallback = -1) const {
        const JsonValue* v = obj.find(key);
        if (!v) {
            if (fallback >= 0) return static_cast<std::uint64_t>(fallback);
            fail(where + " lacks \"" + key + "\"");
        }
        if (!v->is_number() || v->number < 0 || v->number != std::floor(v->number) || v->number > 1e15)
            fail(where + ": \"" + key + "\" is not a non-negative integer");
        return static_cast<std::uint64_t>(v->number);
    }

    const JsonValue& item(const std::string& array, std::uint64_t index) const {
        const JsonValue* a = json_.find(array);
        if (!a || !a->is_array() || index >= a->array.size())
            fail("\"" + array + "\"[" + std::to_string(index) + "] does not exist");
        return a->array[index];
    }

    // Accessor `index`: `components` values of component type `type` per element
    // (any unsigned integer type when `type` is 0); the elements as doubles.
    std::vector<double> accessor(std::uint64_t index, int components, int type) const {
        const std::string where = "accessor " + std::to_string(index);
        const JsonValue& a = item("accessors", index);
        const int component_type = static_cast<int>(integer(a, "componentType", where));
        std::size_t size = 0;
        if (component_type == kFloat) size = 4;
        else if (component_type == kUnsignedInt) size = 4;
        else if (component_type == kUnsignedShort) size = 2;
        else if (component_type == kUnsignedByte) size = 1;
        if (type != 0 ? component_type != type : component_type == kFloat || size == 0)
            fail(where + ": component type " + std::to_string(component_type) + " not expected here");
        const JsonValue* t = a.find("type");
        const char* expected = components == 1 ? "SCALAR" : components == 2 ? "VEC2" : "VEC3";
        if (!t || t->string != expected) fail(where + ": type is not " + expected);
        const std::uint64_t count = integer(a, "count", where);
        if (a.find("sparse")) fail(where + ": sparse accessors are not supported");
        const std::uint64_t view_index = integer(a, "bufferView", where);
        const std::uint64_t offset = integer(a, "byteOffset", where, 0);
        const std::string view_where = "bufferView " + std::to_string(view_index);
        const JsonValue& view = item("bufferViews", view_index);
        if (integer(view, "buffer", view_where) != 0) fail(view_where + ": only buffer 0 (the BIN chunk) is supported");
        const std::uint64_t view_offset = integer(view, "byteOffset", view_where, 0);
        const std::uint64_t view_length = integer(view, "byteLength", view_where);
        const std::uint64_t element = size * components;
        const std::uint64_t stride = integer(view, "byteStride", view_where, static_cast<double>(element));
        if (stride < element) fail(view_where + ": byteStride " + std::to_string(stride) + " below the element size");
        if (view_offset > bin_size_ || view_length > bin_size_ - view_offset)
            fail(view_where + " lies outside the " + std::to_string(bin_size_) + "-byte BIN chunk");
        if (count > 0 && (offset > view_length || (view_length - offset < element) ||
                          (count - 1) > (view_length - offset - element) / stride))
            fail(where + ": " + std::to_string(count) + " elements do not fit " + view_where);
        std::vector<double> values;
        values.reserve(static_cast<std::size_t>(count * components));
        for (std::uint64_t i = 0; i < count; ++i) {
            const std::size_t at = bin_begin_ + view_offset + offset + i * stride;
            ByteCursor in(bytes_, at, at + element, file_);
            for (int c = 0; c < components; ++c) {
                double x = 0;
                if (component_type == kFloat) x = in.f32("an accessor value");
                else if (size == 4) x = in.u32("an index");
                else if (size == 2) x = in.u16("an index");
                else x = in.u8("an index");
                if (!std::isfinite(x)) fail(where + ": element " + std::to_string(i) + " is not finite");
                values.push_back(x);
            }
        }
        return values;
    }

private:
    const JsonValue& json_;
    const std::string& bytes_;
    std::size_t bin_begin_, bin_size_;
    const std::string& file_;
};

}  // namespace

mesh::Mesh read_glb(const std::string& path) { return parse_glb(read_file_bytes(path), path); }

mesh::Mesh parse_glb(const std::string& bytes, const std::string& path) {
    ByteCursor in(bytes, 0, bytes.size(), path);
    if (in.u32("the glb magic") != kGlbMagic) throw geom::ReadError(path, 0, "not a glb file (bad magic)");
    const std::uint32_t version = in.u32("the glb version");
    if (version != 2) throw geom::ReadError(path, 0, "glb version " + std::to_string(version) + ", expected 2");
    const std::uint32_t total = in.u32("the glb length");
    if (total != bytes.size())
        throw geom::ReadError(path, 0, "glb header says " + std::to_string(total) + " bytes, the file has " +
                                           std::to_string(bytes.size()));
    const std::uint32_t json_length = in.u32("the JSON chunk length");
    if (in.u32("the JSON chunk type") != kChunkJson) throw geom::ReadError(path, 0, "first glb chunk is not JSON");
    if (json_length > in.remaining()) throw geom::ReadError(path, 0, "truncated JSON chunk");
    const std::string json_text = bytes.substr(in.position(), json_length);
    in.skip(json_length, "the JSON chunk");
    std::size_t bin_begin = 0, bin_size = 0;
    if (in.remaining() > 0) {
        const std::uint32_t bin_length = in.u32("the BIN chunk length");
        if (in.u32("the BIN chunk type") != kChunkBin) throw geom::ReadError(path, 0, "second glb chunk is not BIN");
        if (bin_length > in.remaining()) throw geom::ReadError(path, 0, "truncated BIN chunk");
        bin_begin = in.position();
        bin_size = bin_length;
    }
    JsonValue json;
    try {
        json = parse_json(json_text);
    } catch (const std::runtime_error& e) {
        throw geom::ReadError(path, 0, std::string("glb JSON chunk: ") + e.what());
    }
    if (!json.is_object()) throw geom::ReadError(path, 0, "glb JSON chunk is not an object");
    const Glb glb(json, bytes, bin_begin, bin_size, path);

    mesh::Mesh mesh;
    bool normals = true, uvs = true;
    std::vector<Eigen::Vector3d> all_normals;
    std::vector<Eigen::Vector2d> all_uvs;
    const JsonValue* meshes = json.find("meshes");
    if (meshes && meshes->is_array()) {
        for (std::size_t m = 0; m < meshes->array.size(); ++m) {
            const JsonValue* primitives = meshes->array[m].find("primitives");
            if (!primitives || !primitives->is_array()) continue;
            for (std::size_t p = 0; p < primitives->array.size(); ++p) {
                const JsonValue& prim = primitives->array[p];
                const std::string where = "mesh " + std::to_string(m) + " primitive " + std::to_string(p);
                if (glb.integer(prim, "mode", where, kTriangles) != kTriangles)
                    glb.fail(where + ": mode is not 4 (triangles)");
                const JsonValue* attributes = prim.find("attributes");
                if (!attributes) glb.fail(where + " lacks attributes");
                const std::vector<double> P = glb.accessor(glb.integer(*attributes, "POSITION", where), 3, kFloat);
                const std::size_t base = mesh.positions.size(), n = P.size() / 3;
                if (base + n > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
                    glb.fail("too many vertices");
                for (std::size_t i = 0; i < n; ++i) mesh.positions.emplace_back(P[3 * i], P[3 * i + 1], P[3 * i + 2]);
                if (attributes->find("NORMAL") && normals) {
                    const std::vector<double> N = glb.accessor(glb.integer(*attributes, "NORMAL", where), 3, kFloat);
                    if (N.size() != P.size()) glb.fail(where + ": NORMAL count differs from POSITION");
                    for (std::size_t i = 0; i < n; ++i) all_normals.emplace_back(N[3 * i], N[3 * i + 1], N[3 * i + 2]);
                } else {
                    normals = false;
                }
                if (attributes->find("TEXCOORD_0") && uvs) {
                    const std::vector<double> T = glb.accessor(glb.integer(*attributes, "TEXCOORD_0", where), 2, kFloat);
                    if (T.size() / 2 != n) glb.fail(where + ": TEXCOORD_0 count differs from POSITION");
                    for (std::size_t i = 0; i < n; ++i) all_uvs.emplace_back(T[2 * i], 1.0 - T[2 * i + 1]);
                } else {
                    uvs = false;
                }
                std::vector<double> I;
                if (prim.find("indices")) {
                    I = glb.accessor(glb.integer(prim, "indices", where), 1, 0);
                } else {
                    I.resize(n);
                    for (std::size_t i = 0; i < n; ++i) I[i] = static_cast<double>(i);
                }
                if (I.size() % 3 != 0) glb.fail(where + ": " + std::to_string(I.size()) + " indices, not a multiple of 3");
                for (std::size_t t = 0; t < I.size(); t += 3) {
                    std::array<std::int32_t, 3> tri;
                    for (int k = 0; k < 3; ++k) {
                        if (I[t + k] >= static_cast<double>(n))
                            glb.fail(where + ": index " + geom::format_value(I[t + k]) + " out of range (" +
                                     std::to_string(n) + " vertices)");
                        tri[k] = static_cast<std::int32_t>(base + static_cast<std::size_t>(I[t + k]));
                    }
                    mesh.triangles.push_back(tri);
                }
            }
        }
    }
    if (normals && !mesh.positions.empty()) mesh.normals = std::move(all_normals);
    if (uvs && !mesh.positions.empty()) mesh.uvs = std::move(all_uvs);
    finish_read_mesh(mesh, path);
    return mesh;
}

}  // namespace trimkit::io
