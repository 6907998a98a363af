#include "geom/rational_weights.h"

#include <cmath>

#include "geom/error.h"

namespace trimkit::geom {

bool validate_rational_weights(const std::vector<double>& weights, const std::string& owner) {
    bool rational = false;
    for (size_t i = 0; i < weights.size(); ++i) {
        if (!(weights[i] > 0.0) || !std::isfinite(weights[i]))
            throw InvalidInput(owner + ": weight[" + std::to_string(i) + "] = " +
                               format_value(weights[i]) +
                               "; rational weights must be finite and > 0");
        if (weights[i] != 1.0) rational = true;
    }
    return rational;
}

}  // namespace trimkit::geom
