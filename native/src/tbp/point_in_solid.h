// Point-in-solid for a closed TBP solid by ray casting through the patches'
// LOD hierarchies ([Garcia] Sec. 3, "Point in solid test", after [GRF04]):
// branches whose boxes the ray misses are skipped, and the ray is intersected
// with the base triangles of the leaves, i.e. the solid is classified against
// its polyhedral approximation at the hierarchy's leaf level (exact for flat
// patches; for curved ones the error shrinks as levels/lod grow). Robustness:
// a ray that passes within kGrazeTolerance of a leaf triangle's edge or vertex,
// or nearly parallel to it, is discarded, and the answer is the majority of
// three rays that were not (from a fixed list of generic directions).
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "tbp/tbp_hierarchy.h"

namespace trimkit::tbp {

enum class Containment { kOutside, kInside, kBoundary };

// A hit within this barycentric distance of a leaf triangle's edge counts as
// grazing (1e-9: rounding of a ray/triangle test is ~1e-15; the margin keeps
// rays away from the seams between leaves and patches).
constexpr double kGrazeTolerance = 1e-9;
// A point closer than this fraction of the solid's box diagonal to the surface
// (along a ray) is on the boundary: rounding of the ray parameter is ~1e-16.
constexpr double kOnSurfaceRelativeTolerance = 1e-12;

struct PointInSolidStats {
    long long box_tests = 0;
    long long triangle_tests = 0;
    long long rejected_rays = 0;
};

// Hierarchies of a closed, outward-oriented solid (build_hierarchies).
// kBoundary if the point lies on the surface; throws NumericalFailure if no
// three usable rays are found among the directions tried.
Containment point_in_solid(const std::vector<TbpHierarchy>& solid, const Eigen::Vector3d& point,
                           PointInSolidStats* stats = nullptr);

// INCLUSION(box, obj) of [Garcia] Alg. 5.1: kInside or kOutside if no leaf box
// of the solid meets `box` (then the whole box is on one side; its centre
// decides), kBoundary (partly inside) otherwise.
Containment box_in_solid(const std::vector<TbpHierarchy>& solid, const Eigen::AlignedBox3d& box,
                         PointInSolidStats* stats = nullptr);

}  // namespace trimkit::tbp
