// Two-sided surface deviation between two models with the same faces (a model
// and its compress -> extend round trip): for each face, surface_deviation from
// A's face onto B's surface and from B's face onto A's, matched by face index.
#pragma once

#include <vector>

#include "geom/model.h"

namespace trimkit::fit {

struct FaceDeviation {
    double a_to_b_avg = 0, a_to_b_max = 0;
    double b_to_a_avg = 0, b_to_a_max = 0;
    int points = 0;  // grid points, both directions
    double max() const { return a_to_b_max > b_to_a_max ? a_to_b_max : b_to_a_max; }
};

// Throws geom::InvalidInput when the face counts differ.
std::vector<FaceDeviation> model_deviation(const geom::Model& a, const geom::Model& b);

}  // namespace trimkit::fit
