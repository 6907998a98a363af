#include "io/write_mesh.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "geom/error.h"
#include "io/write_glb.h"
#include "io/write_obj.h"
#include "io/write_ply.h"
#include "io/write_stl.h"

namespace trimkit::io {

void write_mesh(const std::string& path, const mesh::Mesh& mesh) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".obj") return write_obj(path, mesh);
    if (extension == ".ply") return write_ply(path, mesh);
    if (extension == ".stl") return write_stl(path, mesh);
    if (extension == ".glb") return write_glb(path, mesh);
    throw geom::InvalidInput(path + ": unknown mesh format '" + extension +
                             "'; expected .obj, .ply, .stl or .glb");
}

}  // namespace trimkit::io
