#include "tess/tessellation_options.h"

#include <cmath>

#include "geom/error.h"

namespace trimkit::tess {

void validate(const TessellationOptions& options) {
    using geom::format_value;
    if (!(std::isfinite(options.tolerance) && options.tolerance > 0.0))
        throw geom::InvalidInput("TessellationOptions: tolerance = " +
                                 format_value(options.tolerance) +
                                 "; expected a finite value > 0 (model units)");
    if (!(std::isfinite(options.angle) && options.angle >= 0.0 && options.angle <= M_PI))
        throw geom::InvalidInput("TessellationOptions: angle = " + format_value(options.angle) +
                                 "; expected radians in [0, pi]");
    if (options.threads < 0)
        throw geom::InvalidInput("TessellationOptions: threads = " +
                                 std::to_string(options.threads) + "; expected >= 0 (0 = all cores)");
    if (!(options.face_timeout >= 0.0))
        throw geom::InvalidInput("TessellationOptions: face_timeout = " + format_value(options.face_timeout) +
                                 "; expected seconds >= 0 (0 = no limit)");
}

}  // namespace trimkit::tess
