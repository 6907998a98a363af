// read_step for builds without Open CASCADE (TRIMKIT_WITH_OCCT off): trimkit's own
// reader when asked for (--step-reader own or auto), else a refusal.
#include "io/read_step.h"

#include "geom/error.h"
#include "io/step_geometry.h"

namespace trimkit::io {

geom::Model read_step(const std::string& path, const ReadOptions& options) {
    if (options.step_reader == StepReader::kOcct)
        throw geom::ReadError(path, 0, "STEP import needs trimkit built with Open CASCADE");
    try {
        return read_step_own(path, options);
    } catch (const UnsupportedStepEntity& e) {
        throw geom::ReadError(path, 0, std::string("trimkit's own STEP reader does not take this file (and "
                                                   "Open CASCADE is not built in): ") + e.what());
    }
}

bool step_supported() { return false; }

}  // namespace trimkit::io
