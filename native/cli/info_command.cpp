#include <iostream>

#include "arguments.h"
#include "commands.h"
#include "io/model_summary.h"
#include "io/read_model.h"
#include "read_options.h"

namespace trimkit::cli {

int run_info(const std::vector<std::string>& argv) {
    const Arguments args(argv, {"--json"}, {"--read-timeout", "--step-reader"});
    args.expect_positionals(1, "trimkit info MODEL [--json] [--read-timeout SECONDS] [--step-reader occt|own|auto]");
    const std::string& path = args.positionals()[0];
    const io::ModelSummary summary = io::summarize(io::read_model(path, read_options(args)), path);
    std::cout << (args.flag("--json") ? io::to_json(summary) + "\n" : io::to_text(summary));
    return 0;
}

}  // namespace trimkit::cli
