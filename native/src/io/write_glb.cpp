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

// Appends the mesh's attributes and indices to `bin` (one view each) and returns its
// primitive's JSON object.
std::string append_primitive(const mesh::Mesh& mesh, std::string& bin, std::vector<View>& views) {
    const std::size_t nv = mesh.vertex_count();
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
    std::string attributes = "\"POSITION\":" + std::to_string(views.size() - 1);
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
    views.push_back({start, bin.size() - start, kElementArrayBuffer, kUnsignedInt, 3 * mesh.triangle_count(),
                     "SCALAR", ""});
    return "{\"primitives\":[{\"attributes\":{" + attributes + "},\"indices\":" +
           std::to_string(views.size() - 1) + ",\"mode\":" + std::to_string(kTriangles) + "}]}";
}

// A node's JSON: its mesh, its matrix (column-major, left out when the identity) and name.
std::string node_json(int mesh, const GlbNode& node) {
    std::string json = "{\"mesh\":" + std::to_string(mesh);
    if (node.matrix != Eigen::Matrix4d::Identity()) {
        json += ",\"matrix\":[";
        for (int k = 0; k < 16; ++k) json += (k > 0 ? "," : "") + json_number(node.matrix(k % 4, k / 4));
        json += "]";
    }
    if (!node.name.empty()) json += ",\"name\":" + json_string(node.name);
    return json + "}";
}

void check_node(const GlbNode& node, std::size_t meshes) {
    if (node.mesh < 0 || static_cast<std::size_t>(node.mesh) >= meshes)
        throw geom::InvalidInput("write_glb: node mesh " + std::to_string(node.mesh) + " out of range (" +
                                 std::to_string(meshes) + " meshes)");
    if (!node.matrix.allFinite() || node.matrix.row(3) != Eigen::RowVector4d(0, 0, 0, 1))
        throw geom::InvalidInput("write_glb: a node's matrix is not finite and affine");
}

// The whole .glb file: header, JSON chunk and BIN chunk, padded to 4 bytes.
std::string glb_bytes(std::string json, std::string bin) {
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
    return bytes;
}

}  // namespace

void write_glb(const std::string& path, const mesh::Mesh& mesh) {
    write_glb(path, std::vector<mesh::Mesh>{mesh}, std::vector<GlbNode>{GlbNode{}});
}

void write_glb(const std::string& path, const std::vector<mesh::Mesh>& meshes, const std::vector<GlbNode>& nodes) {
    for (const mesh::Mesh& mesh : meshes) check_float_mesh(mesh, "write_glb");
    for (const GlbNode& node : nodes) check_node(node, meshes.size());
    // Meshes with triangles get glTF mesh indices in order; nodes of the others go.
    std::vector<int> gltf_mesh(meshes.size(), -1);
    std::string bin, mesh_list, node_list, scene_nodes;
    std::vector<View> views;
    int count = 0;
    for (std::size_t m = 0; m < meshes.size(); ++m) {
        if (meshes[m].triangle_count() == 0) continue;
        mesh_list += (count > 0 ? "," : "") + append_primitive(meshes[m], bin, views);
        gltf_mesh[m] = count++;
    }
    int placed = 0;
    for (const GlbNode& node : nodes) {
        if (gltf_mesh[node.mesh] < 0) continue;
        node_list += (placed > 0 ? "," : "") + node_json(gltf_mesh[node.mesh], node);
        scene_nodes += (placed > 0 ? "," : "") + std::to_string(placed);
        ++placed;
    }
    std::string json = R"({"asset":{"version":"2.0","generator":"trimkit"},"scene":0,)";
    if (placed == 0) {
        json += R"("scenes":[{}]})";
        bin.clear();
    } else {
        json += "\"scenes\":[{\"nodes\":[" + scene_nodes + "]}],\"nodes\":[" + node_list + "],\"meshes\":[" +
                mesh_list + "],";
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
    OutputFile out(path);
    out.write(glb_bytes(std::move(json), std::move(bin)));
    out.commit();
}

}  // namespace trimkit::io
