// A .tkz file extended into a model (its compressed faces rebuilt), for the
// commands that read one (extend, check). A face that cannot be rebuilt from the
// file's edges and rules is bad input: geom::ReadError "FILE: a face cannot be
// rebuilt: ...", exit status 2.
#pragma once

#include <string>

#include "geom/model.h"

namespace trimkit::cli {

// Returns the extended model; `rebuilt` (optional) gets the number of faces rebuilt.
geom::Model extended_tkz(const std::string& path, int* rebuilt = nullptr);

}  // namespace trimkit::cli
