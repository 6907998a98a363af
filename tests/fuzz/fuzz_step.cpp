// libFuzzer harness: STEP text through Open CASCADE (read_step: XCAF read, our
// translation of its shapes) and the model's summary. OCCT reads files only, so
// each input goes through this process's scratch file (fuzz::scratch_file). OCCT
// itself is not instrumented: only faults that surface in our code or as signals
// are seen.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "io/model_summary.h"
#include "io/read_step.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace trimkit;
    const std::string path = fuzz::scratch_file(data, size, "input.stp");
    fuzz::expect_bad_input_at_most([&] { io::summarize(io::read_step(path), fuzz::kInputName); });
    return 0;
}
