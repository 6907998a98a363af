#include "io/write_obj.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include "geom/error.h"
#include "io/output_file.h"
#include "io/write_support.h"

namespace trimkit::io {
namespace {

// "color_RRGGBB" from an rgb colour in [0, 1], 8 bits per channel.
std::string material_name(const std::array<float, 3>& rgb) {
    char buf[16];
    const auto byte = [](float c) { return static_cast<unsigned>(std::lround(c * 255.0f)); };
    std::snprintf(buf, sizeof buf, "color_%02X%02X%02X", byte(rgb[0]), byte(rgb[1]), byte(rgb[2]));
    return buf;
}

void write_mtl(const std::string& path, const std::map<std::string, std::array<float, 3>>& colors) {
    std::string text = "# trimkit materials: one per CAD face colour\n";
    for (const auto& [name, rgb] : colors) {
        char kd[64];
        std::snprintf(kd, sizeof kd, "Kd %.6g %.6g %.6g\n", rgb[0], rgb[1], rgb[2]);
        text += "\nnewmtl " + name + "\n" + kd;
    }
    OutputFile out(path);
    out.write(text);
    out.commit();
}

}  // namespace

void write_obj(const std::string& path, const mesh::Mesh& mesh, const ObjOptions& options) {
    try {
        mesh::validate(mesh);
    } catch (const geom::InvalidInput& e) {
        throw geom::InvalidInput(std::string("write_obj: ") + e.what());
    }
    const bool groups = options.face_groups && mesh.has_face_ids();
    const bool materials = options.materials && mesh.has_face_ids() && !mesh.face_colors.empty();
    const std::filesystem::path mtl_path = std::filesystem::path(path).replace_extension(".mtl");

    OutputFile out(path);
    std::string text;
    text.reserve(1 << 20);
    const auto flush_text = [&](bool force) {
        if (force || text.size() >= (1u << 20)) {
            out.write(text);
            text.clear();
        }
    };
    text += "# trimkit OBJ: " + std::to_string(mesh.vertex_count()) + " vertices, " +
            std::to_string(mesh.triangle_count()) + " triangles\n";
    if (materials) text += "mtllib " + mtl_path.filename().string() + "\n";
    for (const auto& p : mesh.positions) {
        text += "v " + shortest_text(p.x()) + " " + shortest_text(p.y()) + " " +
                shortest_text(p.z()) + "\n";
        flush_text(false);
    }
    for (const auto& uv : mesh.uvs) {
        text += "vt " + shortest_text(uv.x()) + " " + shortest_text(uv.y()) + "\n";
        flush_text(false);
    }
    for (const auto& n : mesh.normals) {
        text += "vn " + shortest_text(n.x()) + " " + shortest_text(n.y()) + " " +
                shortest_text(n.z()) + "\n";
        flush_text(false);
    }

    std::map<std::string, std::array<float, 3>> used_colors;
    std::string current_material;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const bool new_face = mesh.has_face_ids() && (t == 0 || mesh.face_ids[t] != mesh.face_ids[t - 1]);
        if (groups && new_face) text += "g face_" + std::to_string(mesh.face_ids[t]) + "\n";
        if (materials && new_face) {
            const auto& rgb = mesh.face_colors[mesh.face_ids[t]];
            const std::string name = material_name(rgb);
            used_colors.emplace(name, rgb);
            if (name != current_material) {
                text += "usemtl " + name + "\n";
                current_material = name;
            }
        }
        text += "f";
        for (std::int32_t v : mesh.triangles[t]) {
            const std::string index = std::to_string(v + 1);
            text += " " + index;
            if (mesh.has_uvs()) text += "/" + index;
            if (mesh.has_normals()) text += (mesh.has_uvs() ? "/" : "//") + index;
        }
        text += "\n";
        flush_text(false);
    }
    flush_text(true);
    out.commit();
    if (materials) write_mtl(mtl_path.string(), used_colors);
}

}  // namespace trimkit::io
