// Sample points on the tangent planes outside a face's region ([Muraki] Sec. 4.3,
// the purple markers of Fig. 11 b) and the intersections of the cross-boundary
// derivatives with the reference planes (Sec. 4.1, Fig. 9 a). From each boundary
// sample x with tangent t and normal n, the cross-boundary line x + s d, d = t x n
// (pointing away from the face, which lies on the left of t), runs in the tangent
// plane until it meets a reference plane, or, when it would enter the region
// again first (a concave notch, across a hole), to half way there.
#pragma once

#include <array>
#include <utility>
#include <vector>

#include "fit/boundary_samples.h"
#include "fit/fit_surface.h"
#include "fit/local_frame.h"
#include "fit/loop_polygons.h"

namespace trimkit::fit {

// Samples per cross-boundary line (its start, the boundary point, excluded).
constexpr int kLineSamples = 4;
// Points per line tested against the region for a re-entry.
constexpr int kEntryChecks = 16;
// A line whose direction projects on the reference plane shorter than this
// (a tangent plane nearly perpendicular to it, Sec. 6 "periodic shapes") is not used.
constexpr double kMinPlanarDirection = 0.2;

struct OutsideSamples {
    std::vector<SurfaceSample> points;
    // Per reference plane (0: x = x0, 1: x = x1, 2: y = y0, 3: y = y1): the
    // parameter along it (v for 0 and 1, u for 2 and 3) and the intersection point.
    std::array<std::vector<std::pair<double, Eigen::Vector3d>>, 4> sides;
};

// normals[k] belongs to samples[k] (unit, oriented like frame.n);
// region: the boundary loops projected on the reference plane (frame.plane).
OutsideSamples outside_samples(const std::vector<BoundarySample>& samples, const std::vector<Eigen::Vector3d>& normals,
                               const LocalFrame& frame, const LoopPolygons& region);

}  // namespace trimkit::fit
