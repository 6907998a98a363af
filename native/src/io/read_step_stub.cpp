// read_step for builds without Open CASCADE (TRIMKIT_WITH_OCCT off): always refuses.
#include "io/read_step.h"

#include "geom/error.h"

namespace trimkit::io {

geom::Model read_step(const std::string& path, const ReadOptions&) {
    throw geom::ReadError(path, 0, "STEP import needs trimkit built with Open CASCADE");
}

bool step_supported() { return false; }

}  // namespace trimkit::io
