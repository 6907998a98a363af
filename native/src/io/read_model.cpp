#include "io/read_model.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "geom/error.h"
#include "io/read_brep.h"
#include "io/read_iges.h"
#include "io/read_step.h"
#include "io/tkz_format.h"

namespace trimkit::io {

geom::Model read_model(const std::string& path, const ReadOptions& options) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".igs" || ext == ".iges") return read_iges(path, options);
    if (ext == ".stp" || ext == ".step") return read_step(path, options);
    if (ext == ".brep" || ext == ".brp") return read_brep(path, options);
    if (ext == ".tkz") return read_tkz_model(path);
    throw geom::ReadError(path, 0, "unsupported file type '" + ext +
                                       "'; expected .igs, .iges, .stp, .step, .brep or .tkz");
}

}  // namespace trimkit::io
