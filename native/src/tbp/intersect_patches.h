// Patch/patch intersection through the LOD hierarchies ([Garcia] Sec. 4):
// TBP_INT (Algorithm 4.1) descends both trees, pruning node pairs whose boxes
// do not meet and splitting the node with the larger box; at the leaves the
// base triangles are intersected (TR_INT, Moller) and each segment carries its
// parameters (u,v,w) on both root patches. ADD_SEGMENTS (Alg. 4.2) and
// BUILD_COMPONENTS (Alg. 4.3) link the segments into components: closed loops,
// open curves, and branches meeting at Y-shaped junctions.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "tbp/tbp_hierarchy.h"

namespace trimkit::tbp {

// Segment ends closer than this fraction of the two patches' box diagonal are
// the same point: leaf corners reached by different subdivision paths differ by
// rounding (~1e-15 relative); 1e-10 links them and stays far below a leaf's size.
constexpr double kLinkRelativeTolerance = 1e-10;

struct IntersectionPoint {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  // model space
    Eigen::Vector3d uvw_a = Eigen::Vector3d::Zero();     // parameters on patch A (root domain)
    Eigen::Vector3d uvw_b = Eigen::Vector3d::Zero();     // parameters on patch B
};

// One leaf-level segment, with the leaves (indices in each hierarchy's leaf level) it came from.
struct IntersectionSegment {
    std::array<IntersectionPoint, 2> ends;
    int leaf_a = -1, leaf_b = -1;
};

// A connected piece of the intersection curve: a polyline of points, closed
// (last point joins the first, not repeated) or open. An open component's end
// is either a free end (on a patch boundary) or a Y junction (see junctions).
struct IntersectionComponent {
    std::vector<IntersectionPoint> points;
    bool closed = false;
};

struct IntersectionStats {
    long long box_tests = 0;       // node box pairs tested
    long long triangle_tests = 0;  // leaf base-triangle pairs tested (TR_INT calls)
    long long segments = 0;        // segments found by TR_INT
};

struct PatchIntersection {
    std::vector<IntersectionSegment> segments;  // distinct segments (ADD_SEGMENTS output)
    std::vector<IntersectionComponent> components;
    std::vector<Eigen::Vector3d> junctions;  // points where three or more branches meet
    IntersectionStats stats;
};

// TBP_INT at the leaves of both hierarchies (max_level = each tree's levels()).
// With use_hierarchy false, every leaf pair is tested (for the counts the
// hierarchy saves; same result).
PatchIntersection intersect_patches(const TbpHierarchy& a, const TbpHierarchy& b, bool use_hierarchy = true);

// TBP_INT only: appends the leaf segments to `out` and counts tests in `stats`.
void intersect_leaves(const TbpHierarchy& a, const TbpHierarchy& b, bool use_hierarchy,
                      std::vector<IntersectionSegment>& out, IntersectionStats& stats);

// ADD_SEGMENTS + BUILD_COMPONENTS: link `segments` (ends within `tolerance`
// are one point), drop duplicates and zero-length ones, and split the result
// into components. Departure from Alg. 4.2/4.3: the segments are linked as a
// graph (vertices = welded ends) instead of an ordered list with a separate
// potential_loop_segments store; a vertex of degree >= 3 is a Y junction, a
// chain of degree-2 vertices between junctions or ends is one component, a
// cycle without junctions is a closed component, and a chain that returns to
// its own junction is cut there and saved as a closed component.
void build_components(PatchIntersection& result, double tolerance);

// Intersection of two solids (or any two sets of patches): the segments of
// every patch pair, linked into components over both sets (a curve crossing
// patch boundaries is one component) with kLinkRelativeTolerance x the
// diagonal of all the patches' boxes. Leaf indices in the segments refer to
// each pair's own hierarchies.
PatchIntersection intersect_solids(const std::vector<TbpHierarchy>& a, const std::vector<TbpHierarchy>& b,
                                   bool use_hierarchy = true);

}  // namespace trimkit::tbp
