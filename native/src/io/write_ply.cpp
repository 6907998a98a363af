#include "io/write_ply.h"

#include "io/output_file.h"
#include "io/write_support.h"

namespace trimkit::io {

void write_ply(const std::string& path, const mesh::Mesh& mesh) {
    check_float_mesh(mesh, "write_ply");
    std::string header = "ply\nformat binary_little_endian 1.0\ncomment written by trimkit\n";
    header += "element vertex " + std::to_string(mesh.vertex_count()) + "\n";
    header += "property float x\nproperty float y\nproperty float z\n";
    if (mesh.has_normals()) header += "property float nx\nproperty float ny\nproperty float nz\n";
    if (mesh.has_uvs()) header += "property float u\nproperty float v\n";
    header += "element face " + std::to_string(mesh.triangle_count()) + "\n";
    header += "property list uchar int vertex_indices\n";
    if (mesh.has_face_ids()) header += "property int face_id\n";
    header += "end_header\n";

    std::string bytes;
    const std::size_t vertex_size = 4 * (3 + (mesh.has_normals() ? 3 : 0) + (mesh.has_uvs() ? 2 : 0));
    const std::size_t face_size = 1 + 12 + (mesh.has_face_ids() ? 4 : 0);
    bytes.reserve(header.size() + vertex_size * mesh.vertex_count() + face_size * mesh.triangle_count());
    bytes += header;
    for (std::size_t i = 0; i < mesh.vertex_count(); ++i) {
        for (int k = 0; k < 3; ++k) put_f32(bytes, static_cast<float>(mesh.positions[i][k]));
        if (mesh.has_normals())
            for (int k = 0; k < 3; ++k) put_f32(bytes, static_cast<float>(mesh.normals[i][k]));
        if (mesh.has_uvs())
            for (int k = 0; k < 2; ++k) put_f32(bytes, static_cast<float>(mesh.uvs[i][k]));
    }
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        put_u8(bytes, 3);
        for (std::int32_t v : mesh.triangles[t]) put_i32(bytes, v);
        if (mesh.has_face_ids()) put_i32(bytes, mesh.face_ids[t]);
    }

    OutputFile out(path);
    out.write(bytes);
    out.commit();
}

}  // namespace trimkit::io
