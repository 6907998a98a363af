// libFuzzer harness: .brep text through Open CASCADE (read_brep: the counts checked
// by io/brep_counts, BRepTools::Read on io/brep_input's stream, our translation of
// the shape) and the model's summary, through this process's scratch file
// (fuzz::scratch_file), as fuzz_step.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_support.h"
#include "io/model_summary.h"
#include "io/read_brep.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace trimkit;
    const std::string path = fuzz::scratch_file(data, size, "input.brep");
    fuzz::expect_bad_input_at_most([&] { io::summarize(io::read_brep(path), fuzz::kInputName); });
    return 0;
}
