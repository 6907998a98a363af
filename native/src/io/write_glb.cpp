#include "io/write_glb.h"

#include <algorithm>
#include <limits>

#include "geom/error.h"
#include "io/json_writer.h"
#include "io/output_file.h"
#include "io/write_support.h"

namespace trimkit::io {
namespace {

// glTF 2.0 constants (glTF spec Sec. 4.4 "Binary glTF layout", 5.1 accessor component types).
constexpr std::uint32_t kGlbMagic = 0x46546C67;      // "glTF"
constexpr std::uint32_t kGlbVersion = 2;
constexpr std::uint32_t kChunkJson = 0x4E4F534A;     // "JSON"
constexpr std::uint32_t kChunkBin = 0x004E4942;      // "BIN\0"
constexpr int kFloat = 5126;
constexpr int kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;
constexpr int kTriangles = 4;

// One accessor over its own tightly packed buffer view.
struct View {
    std::size_t offset, length;
    int target, component_type;
    std::size_t count;
    const char* type;
    std::string min_max;  // ,"min":[..],"max":[..] or empty
};

std::string float_list(const float* v, int n) {
    std::string text = "[";
    for (int k = 0; k < n; ++k) text += (k > 0 ? "," : "") + json_number(v[k]);
    return text + "]";
}

}  // namespace

void write_glb(const std::string& path, const mesh::Mesh& mesh) {
    check_float_mesh(mesh, "write_glb");
    const std::size_t nv = mesh.vertex_count();
    const std::size_t nt = mesh.triangle_count();

    std::string bin;
    std::vector<View> views;
    std::string attributes;
    std::string json = R"({"asset":{"version":"2.0","generator":"trimkit"},"scene":0,)";
    if (nt == 0) {
        json += R"("scenes":[{}]})";
    } else {
        bin.reserve(nv * 4 * (3 + (mesh.has_normals() ? 3 : 0) + (mesh.has_uvs() ? 2 : 0)) + nt * 12);
        // POSITION: min/max of the float32 values actually stored (the spec requires them exact).
        float lo[3], hi[3];
        std::fill(lo, lo + 3, std::numeric_limits<float>::infinity());
        std::fill(hi, hi + 3, -std::numeric_limits<float>::infinity());
        std::size_t start = bin.size();
        for (const auto& p : mesh.positions) {
            for (int k = 0; k < 3; ++k) {
                const auto x = static_cast<float>(p[k]);
                lo[k] = std::min(lo[k], x);
                hi[k] = std::max(hi[k], x);
                put_f32(bin, x);
            }
        }
        views.push_back({start, bin.size() - start, kArrayBuffer, kFloat, nv, "VEC3",
                         ",\"min\":" + float_list(lo, 3) + ",\"max\":" + float_list(hi, 3)});
        attributes = "\"POSITION\":0";
        if (mesh.has_normals()) {
            start = bin.size();
            for (const auto& n : mesh.normals)
                for (int k = 0; k < 3; ++k) put_f32(bin, static_cast<float>(n[k]));
            views.push_back({start, bin.size() - start, kArrayBuffer, kFloat, nv, "VEC3", ""});
            attributes += ",\"NORMAL\":" + std::to_string(views.size() - 1);
        }
        if (mesh.has_uvs()) {
            start = bin.size();
            for (const auto& uv : mesh.uvs) {
                put_f32(bin, static_cast<float>(uv.x()));
                put_f32(bin, static_cast<float>(1.0 - uv.y()));  // glTF origin top left
            }
            views.push_back({start, bin.size() - start, kArrayBuffer, kFloat, nv, "VEC2", ""});
            attributes += ",\"TEXCOORD_0\":" + std::to_string(views.size() - 1);
        }
        start = bin.size();
        for (const auto& t : mesh.triangles)
            for (std::int32_t v : t) put_u32(bin, static_cast<std::uint32_t>(v));
        views.push_back({start, bin.size() - start, kElementArrayBuffer, kUnsignedInt, 3 * nt,
                         "SCALAR", ""});
        const std::size_t indices = views.size() - 1;

        json += R"("scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],"meshes":[{"primitives":[{"attributes":{)" +
                attributes + "},\"indices\":" + std::to_string(indices) +
                ",\"mode\":" + std::to_string(kTriangles) + "}]}],";
        json += "\"buffers\":[{\"byteLength\":" + std::to_string(bin.size()) + "}],";
        std::string buffer_views = "\"bufferViews\":[", accessors = "\"accessors\":[";
        for (std::size_t i = 0; i < views.size(); ++i) {
            const View& v = views[i];
            const char* sep = i > 0 ? "," : "";
            buffer_views += sep + ("{\"buffer\":0,\"byteOffset\":" + std::to_string(v.offset) +
                                   ",\"byteLength\":" + std::to_string(v.length) +
                                   ",\"target\":" + std::to_string(v.target) + "}");
            accessors += sep + ("{\"bufferView\":" + std::to_string(i) +
                                ",\"componentType\":" + std::to_string(v.component_type) +
                                ",\"count\":" + std::to_string(v.count) + ",\"type\":\"" + v.type +
                                "\"" + v.min_max + "}");
        }
        json += buffer_views + "]," + accessors + "]}";
    }

    // Chunks padded to 4 bytes: JSON with spaces, BIN with zeros (glTF spec Sec. 4.4.3).
    while (json.size() % 4 != 0) json += ' ';
    while (bin.size() % 4 != 0) bin += '\0';
    const std::size_t total = 12 + 8 + json.size() + (bin.empty() ? 0 : 8 + bin.size());
    if (total > std::numeric_limits<std::uint32_t>::max())
        throw geom::InvalidInput("write_glb: " + std::to_string(total) +
                                 " bytes exceed the 4 GiB limit of a .glb file");
    std::string bytes;
    bytes.reserve(total);
    put_u32(bytes, kGlbMagic);
    put_u32(bytes, kGlbVersion);
    put_u32(bytes, static_cast<std::uint32_t>(total));
    put_u32(bytes, static_cast<std::uint32_t>(json.size()));
    put_u32(bytes, kChunkJson);
    bytes += json;
    if (!bin.empty()) {
        put_u32(bytes, static_cast<std::uint32_t>(bin.size()));
        put_u32(bytes, kChunkBin);
        bytes += bin;
    }
    OutputFile out(path);
    out.write(bytes);
    out.commit();
}

}  // namespace trimkit::io
