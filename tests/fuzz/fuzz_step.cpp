// libFuzzer harness: STEP text through Open CASCADE (read_step: XCAF read, our
// translation of its shapes) and the model's summary. OCCT reads files only, so
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
#include "io/read_step.h"

namespace {

const std::string& scratch_path() {
    static const std::string path = [] {
        const char* dir = std::getenv("TMPDIR");
        return std::string(dir && *dir ? dir : "/tmp") + "/trimkit-fuzz-step-" + std::to_string(getpid()) + ".stp";
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
    fuzz::expect_bad_input_at_most([&] { io::summarize(io::read_step(scratch_path()), fuzz::kInputName); });
    return 0;
}
