#include "io/write_stl.h"

#include <initializer_list>

#include "io/output_file.h"
#include "io/write_support.h"

namespace trimkit::io {

void write_stl(const std::string& path, const mesh::Mesh& mesh) {
    check_float_mesh(mesh, "write_stl");
    std::string bytes = "binary STL written by trimkit";
    bytes.resize(80, ' ');
    bytes.reserve(84 + 50 * mesh.triangle_count());
    put_u32(bytes, static_cast<std::uint32_t>(mesh.triangle_count()));
    for (const auto& t : mesh.triangles) {
        const Eigen::Vector3d& a = mesh.positions[t[0]];
        const Eigen::Vector3d& b = mesh.positions[t[1]];
        const Eigen::Vector3d& c = mesh.positions[t[2]];
        Eigen::Vector3d n = (b - a).cross(c - a);
        const double length = n.norm();
        n = length > 0.0 ? Eigen::Vector3d(n / length) : Eigen::Vector3d::Zero();
        for (const Eigen::Vector3d* v : std::initializer_list<const Eigen::Vector3d*>{&n, &a, &b, &c})
            for (int k = 0; k < 3; ++k) put_f32(bytes, static_cast<float>((*v)[k]));
        put_u16(bytes, 0);
    }
    OutputFile out(path);
    out.write(bytes);
    out.commit();
}

}  // namespace trimkit::io
