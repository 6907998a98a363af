// The grid half of [Muraki] Sec. 4.4's error evaluation: a 21 x 21 grid (20
// sections each way) over the (u, v) box of a face's outer loop, the points inside
// the outer loop evaluated on the face's surface and projected onto another
// surface (closest point, geom::SurfaceProjector). Used by evaluate_fit and, in
// both directions, by `trimkit check A B` between two models.
// Departure: the grid spans the outer loop's (u, v) box rather than the whole
// surface domain, so a small face on a large surface still gets ~400 points.
#pragma once

#include <Eigen/Geometry>

#include "geom/face.h"

namespace trimkit::fit {

constexpr int kErrorGridSections = 20;

struct SurfaceDeviation {
    double avg = 0, max = 0;
    int points = 0;
    Eigen::AlignedBox3d box;  // of the grid points on the source surface
};

SurfaceDeviation surface_deviation(const geom::Face& source, const geom::NurbsSurface& target);

}  // namespace trimkit::fit
