// libFuzzer harness: GLB bytes -> Mesh (parse_glb, which also validates the mesh).
#include "fuzz_support.h"
#include "io/read_mesh.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace trimkit;
    fuzz::expect_bad_input_at_most([&] { io::parse_glb(fuzz::input_text(data, size), fuzz::kInputName); });
    return 0;
}
