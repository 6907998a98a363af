#include "tkz_model.h"

#include "fit/extend_model.h"
#include "geom/error.h"
#include "io/tkz_format.h"

namespace trimkit::cli {

geom::Model extended_tkz(const std::string& path, int* rebuilt) {
    const fit::CompressedModel compressed = io::read_tkz(path);
    if (rebuilt) {
        *rebuilt = 0;
        for (const auto& rule : compressed.rules) *rebuilt += rule.has_value();
    }
    try {
        return fit::extend_model(compressed);
    } catch (const geom::NumericalFailure& e) {
        // The file's edges and rules are what the fit ran on: a degenerate fit is bad input.
        throw geom::ReadError(path, 0, std::string("a face cannot be rebuilt: ") + e.what());
    } catch (const geom::InvalidInput& e) {
        throw geom::ReadError(path, 0, std::string("a face cannot be rebuilt: ") + e.what());
    }
}

}  // namespace trimkit::cli
