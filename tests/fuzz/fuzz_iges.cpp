// libFuzzer harness: IGES text -> IgesFile -> Model (read_iges_text), its summary,
// instances flattened, then the first kMeshedFaces faces tessellated at a coarse
// relative tolerance on one thread, so that hostile geometry reaches the mesher too.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

#include "fuzz_support.h"
#include "geom/flatten_instances.h"
#include "geom/select_faces.h"
#include "io/model_summary.h"
#include "io/read_iges.h"
#include "tess/tessellate_model.h"

namespace {

// Faces meshed per input, and the tolerance as a fraction of their diagonal: few
// and coarse, so an input costs milliseconds and a slow one points at a real hang.
constexpr int kMeshedFaces = 3;
constexpr double kRelativeTolerance = 0.02;
// Wall time per face, seconds: a face that needs more is reported as a timeout (the
// product's limit, tested here at a size the sanitizers' 10-100x slowdown allows).
constexpr double kFaceTimeout = 5.0;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace trimkit;
    fuzz::expect_bad_input_at_most([&] {
        const geom::Model read = io::read_iges_text(fuzz::input_text(data, size), fuzz::kInputName);
        io::summarize(read, fuzz::kInputName);
        const geom::Model model = geom::flatten_instances(read);
        std::vector<int> first(std::min<std::size_t>(kMeshedFaces, model.faces.size()));
        std::iota(first.begin(), first.end(), 0);
        const geom::Model part = geom::select_faces(model, first);
        const double diagonal = tess::model_diagonal(part);
        if (!(diagonal > 0.0) || !std::isfinite(diagonal)) return;
        tess::TessellationOptions options;
        options.tolerance = kRelativeTolerance * diagonal;
        options.threads = 1;
        options.face_timeout = kFaceTimeout;
        tess::tessellate_model(part, options);
    });
    return 0;
}
