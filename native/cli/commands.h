// The `trimkit` subcommands. Each takes the arguments after its name, prints
// its result to stdout and returns the exit status; errors are thrown
// (UsageError, geom::ReadError, geom::InvalidInput -> 2; others -> 1).
#pragma once

#include <string>
#include <vector>

namespace trimkit::cli {

// trimkit info MODEL [--json]
int run_info(const std::vector<std::string>& args);

// trimkit mesh MODEL -o OUT --tolerance T [--relative] [--angle A] [--mode M]
//   [--trim-method M] [--threads N] [--json]
int run_mesh(const std::vector<std::string>& args);

// trimkit check MODEL MESH [--json] [--samples N] [--threads N]
int run_check(const std::vector<std::string>& args);

// trimkit tbp mesh|intersect|trim|inside|from-mesh ... (TBP solids, [Garcia])
int run_tbp(const std::vector<std::string>& args);

// trimkit compress MODEL -o OUT.tkz [--tolerance T] ([Muraki])
int run_compress(const std::vector<std::string>& args);

// trimkit extend IN.tkz -o MODEL.igs
int run_extend(const std::vector<std::string>& args);

}  // namespace trimkit::cli
