// Error evaluation of a fitted surface against the face it replaces ([Muraki]
// Sec. 4.4, Tab. 1): a 21 x 21 grid (20 sections each way) on the source surface,
// the grid points inside the outer loop projected onto the fitted surface
// (closest point, surface_deviation), and the face's boundary edges sampled and
// projected the same way; average and maximum distances, and the maximum's ratio
// to the face's box.
#pragma once

#include <vector>

#include "geom/model.h"

namespace trimkit::fit {

struct FitError {
    double surface_avg = 0, surface_max = 0;  // grid points -> fitted surface
    double edge_avg = 0, edge_max = 0;        // boundary edges -> fitted surface
    double box_diagonal = 0;                  // the face's box (grid points and edges)
    int grid_points = 0;
    double max() const { return surface_max > edge_max ? surface_max : edge_max; }
    double ratio() const { return box_diagonal > 0 ? max() / box_diagonal : 0.0; }
};

// source: the face with its own surface and (u, v) loops; edges: the model's
// edges its coedges refer to (each must have a 3D curve).
FitError evaluate_fit(const geom::Face& source, const std::vector<geom::Edge>& edges, const geom::NurbsSurface& fitted);

}  // namespace trimkit::fit
