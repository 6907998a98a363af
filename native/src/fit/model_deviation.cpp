#include "fit/model_deviation.h"

#include <string>

#include "fit/surface_deviation.h"
#include "geom/error.h"

namespace trimkit::fit {

std::vector<FaceDeviation> model_deviation(const geom::Model& a, const geom::Model& b) {
    if (a.faces.size() != b.faces.size())
        throw geom::InvalidInput("check: the models have " + std::to_string(a.faces.size()) + " and " +
                                 std::to_string(b.faces.size()) + " faces; expected the same faces");
    std::vector<FaceDeviation> out(a.faces.size());
    for (std::size_t f = 0; f < a.faces.size(); ++f) {
        const SurfaceDeviation ab = surface_deviation(a.faces[f], b.faces[f].surface);
        const SurfaceDeviation ba = surface_deviation(b.faces[f], a.faces[f].surface);
        out[f] = {ab.avg, ab.max, ba.avg, ba.max, ab.points + ba.points};
    }
    return out;
}

}  // namespace trimkit::fit
