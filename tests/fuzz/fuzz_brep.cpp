// libFuzzer harness: .brep text through Open CASCADE (read_brep: the counts checked
// by io/brep_counts, BRepTools::Read on io/brep_input's stream, our translation of
// the shape) and the model's summary. OCCT reads files only, so
// each input is written to one scratch file per process (in $TMPDIR, else /tmp;
// tests/fuzz/run points it at /dev/shm). OCCT itself is not instrumented: only
// faults that surface in our code or as signals are seen.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include <unistd.h>

#include "fuzz_support.h"
#include "io/model_summary.h"
#include "io/read_brep.h"

namespace {

const std::string& scratch_path() {
    static const std::string path = [] {
        const char* dir = std::getenv("TMPDIR");
        return std::string(dir && *dir ? dir : "/tmp") + "/trimkit-fuzz-brep-" + std::to_string(getpid()) + ".brep";
    }();
    return path;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace trimkit;
    {
        std::ofstream out(scratch_path(), std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
        if (!out) std::abort();  // the harness's own failure, not the input's
    }
    fuzz::expect_bad_input_at_most([&] { io::summarize(io::read_brep(scratch_path()), fuzz::kInputName); });
    return 0;
}
