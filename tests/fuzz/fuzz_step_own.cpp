// libFuzzer harness: STEP text through trimkit's own reader (io/read_step_native.h:
// Part 21, geometry, topology and face loops; no OCCT) and the model's summary. A
// file it does not take on (UnsupportedStepEntity) is an answer, as a ReadError is.
#include <string>

#include "fuzz_support.h"
#include "io/model_summary.h"
#include "io/read_monitor.h"
#include "io/read_step_native.h"
#include "io/step_geometry.h"

namespace {
// The read's own limit (checked between faces), well inside the fuzzer's 60 s per input.
constexpr double kReadSeconds = 10.0;
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace trimkit;
    fuzz::expect_bad_input_at_most([&] {
        try {
            io::ReadOptions options;
            options.timeout = kReadSeconds;
            io::ReadMonitor monitor(fuzz::kInputName, options);
            io::summarize(io::read_step_native(fuzz::input_text(data, size), fuzz::kInputName, monitor),
                          fuzz::kInputName);
        } catch (const io::UnsupportedStepEntity&) {
        } catch (const io::ReadStopped&) {
        }
    });
    return 0;
}
