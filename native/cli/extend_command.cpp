// trimkit extend IN.tkz -o MODEL.igs: the compressed faces' surfaces rebuilt from
// their edges and rules (fit::extend_model), the model written as IGES.
#include <cstdio>
#include <filesystem>

#include "arguments.h"
#include "commands.h"
#include "fit/extend_model.h"
#include "geom/error.h"
#include "geom/flatten_instances.h"
#include "io/tkz_format.h"
#include "io/write_iges.h"

namespace trimkit::cli {

int run_extend(const std::vector<std::string>& argv) {
    const char* const usage = "trimkit extend IN.tkz -o MODEL.igs";
    const Arguments args(argv, {}, {"--output"});
    args.expect_positionals(1, usage);
    const std::string out = args.value("--output", "");
    const std::string ext = std::filesystem::path(out).extension().string();
    if (out.empty() || (ext != ".igs" && ext != ".iges"))
        throw UsageError(std::string("expected -o MODEL.igs; usage: ") + usage);
    const fit::CompressedModel compressed = io::read_tkz(args.positionals()[0]);
    int rebuilt = 0;
    for (const auto& rule : compressed.rules) rebuilt += rule.has_value();
    // IGES gets every placed face (subfigures and assemblies flattened), as `mesh` sees them.
    geom::Model model;
    try {
        model = geom::flatten_instances(fit::extend_model(compressed));
    } catch (const geom::NumericalFailure& e) {
        // The file's edges and rules are what the fit ran on: a degenerate fit is bad input.
        throw geom::ReadError(args.positionals()[0], 0, std::string("a face cannot be rebuilt: ") + e.what());
    } catch (const geom::InvalidInput& e) {
        throw geom::ReadError(args.positionals()[0], 0, std::string("a face cannot be rebuilt: ") + e.what());
    }
    io::write_iges(model, out);
    std::printf("faces: %zu, %d rebuilt from their edges; wrote %s\n", model.faces.size(), rebuilt, out.c_str());
    return 0;
}

}  // namespace trimkit::cli
