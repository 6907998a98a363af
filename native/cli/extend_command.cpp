// trimkit extend IN.tkz -o MODEL.igs: the compressed faces' surfaces rebuilt from
// their edges and rules (fit::extend_model), the model written as IGES.
#include <cstdio>
#include <filesystem>

#include "arguments.h"
#include "commands.h"
#include "geom/flatten_instances.h"
#include "io/write_iges.h"
#include "io/tkz_format.h"

namespace trimkit::cli {

int run_extend(const std::vector<std::string>& argv) {
    const char* const usage = "trimkit extend IN.tkz -o MODEL.igs";
    const Arguments args(argv, {}, {"--output"});
    args.expect_positionals(1, usage);
    const std::string out = args.value("--output", "");
    const std::string ext = std::filesystem::path(out).extension().string();
    if (out.empty() || (ext != ".igs" && ext != ".iges"))
        throw UsageError(std::string("expected -o MODEL.igs; usage: ") + usage);
    int rebuilt = 0;
    // IGES gets every placed face (subfigures and assemblies flattened), as `mesh` sees them.
    const geom::Model model = geom::flatten_instances(io::read_tkz_model(args.positionals()[0], &rebuilt));
    io::write_iges(model, out);
    std::printf("faces: %zu, %d rebuilt from their edges; wrote %s\n", model.faces.size(), rebuilt, out.c_str());
    return 0;
}

}  // namespace trimkit::cli
