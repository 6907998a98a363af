// read_step_own: the file's bytes to read_step_native under a ReadMonitor (built with
// and without OCCT).
#include "io/read_step.h"
#include "io/read_step_native.h"
#include "io/read_support.h"

namespace trimkit::io {

geom::Model read_step_own(const std::string& path, const ReadOptions& options) {
    ReadMonitor monitor(path, options);
    return read_step_native(read_file_bytes(path), path, monitor);
}

}  // namespace trimkit::io
