// libFuzzer harness: .tbp JSON -> TbpSolid (parse_tbp), then the solid
// polygonized at level 1, lod 1 (rate 2), as `trimkit tbp mesh` does.
#include "fuzz_support.h"
#include "io/tbp_format.h"
#include "tbp/polygonize.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace trimkit;
    fuzz::expect_bad_input_at_most([&] {
        const tbp::TbpSolid solid = io::parse_tbp(fuzz::input_text(data, size), fuzz::kInputName);
        tbp::PolygonizeOptions options;
        options.level = 1;
        options.lod = 1;
        tbp::polygonize(solid, options);
    });
    return 0;
}
