// Periodic faces, which [Muraki] Sec. 6 says the method cannot handle (reference
// planes and cross-boundary derivatives lie parallel; the paper splits them by hand):
// a face that uses one edge twice (a seam), or whose surface is closed in a direction
// that its loops span. compress_model keeps their surface.
#pragma once

#include "geom/face.h"

namespace trimkit::fit {

// Fraction of a closed direction's period the loops must span to make the face periodic.
constexpr double kPeriodicSpan = 0.99;

// size: the face's extent (model units), for the closure tolerance (1e-7 of it).
bool is_periodic_face(const geom::Face& face, double size);

}  // namespace trimkit::fit
