#include "read_options.h"

namespace trimkit::cli {

io::ReadOptions read_options(const Arguments& args) {
    io::ReadOptions options;
    options.timeout = args.number("--read-timeout", io::kDefaultReadTimeout);
    if (!(options.timeout >= 0.0)) throw UsageError("--read-timeout must be seconds >= 0 (0 = no limit)");
    return options;
}

}  // namespace trimkit::cli
