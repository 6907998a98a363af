// libFuzzer harness: OBJ text -> Mesh (parse_obj), then, for small meshes, the
// PN-triangle solid `trimkit tbp from-mesh` builds from it.
#include "fuzz_support.h"
#include "io/read_mesh.h"
#include "tbp/from_mesh.h"

namespace {

// Meshes up to this many triangles also go through pn_triangles.
constexpr std::size_t kMaxPnTriangles = 256;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace trimkit;
    fuzz::expect_bad_input_at_most([&] {
        const mesh::Mesh mesh = io::parse_obj(fuzz::input_text(data, size), fuzz::kInputName);
        if (mesh.triangle_count() > 0 && mesh.triangle_count() <= kMaxPnTriangles) tbp::pn_triangles(mesh);
    });
    return 0;
}
