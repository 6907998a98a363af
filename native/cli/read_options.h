// The --read-timeout option every command that reads a model takes.
#pragma once

#include "arguments.h"
#include "io/read_options.h"

namespace trimkit::cli {

// --read-timeout SECONDS (default io::kDefaultReadTimeout, 0 = no limit); throws
// UsageError for a negative value.
io::ReadOptions read_options(const Arguments& args);

}  // namespace trimkit::cli
