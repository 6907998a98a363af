#include "io/read_mesh.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "geom/error.h"

namespace trimkit::io {

mesh::Mesh read_mesh(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".ply") return read_ply(path);
    if (ext == ".obj") return read_obj(path);
    if (ext == ".stl") return read_stl(path);
    if (ext == ".glb") return read_glb(path);
    throw geom::ReadError(path, 0, "unknown mesh format '" + ext +
                                       "'; expected .obj, .ply, .stl or .glb");
}

}  // namespace trimkit::io
