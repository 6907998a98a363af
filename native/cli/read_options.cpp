#include "read_options.h"

namespace trimkit::cli {

io::ReadOptions read_options(const Arguments& args) {
    io::ReadOptions options;
    options.timeout = args.number("--read-timeout", io::kDefaultReadTimeout);
    if (!(options.timeout >= 0.0)) throw UsageError("--read-timeout must be seconds >= 0 (0 = no limit)");
    const std::string reader = args.value("--step-reader", "occt");
    if (reader == "occt") options.step_reader = io::StepReader::kOcct;
    else if (reader == "own") options.step_reader = io::StepReader::kOwn;
    else if (reader == "auto") options.step_reader = io::StepReader::kAuto;
    else throw UsageError("--step-reader must be occt, own or auto");
    return options;
}

}  // namespace trimkit::cli
