// Trimming a TBP against a TBP solid ([Garcia] Sec. 5, Algorithm 5.1):
//  a) intersect the patch's hierarchy with every patch of the solid (TBP_INT);
//  b) combine the cut segments with the patch's own boundary, split at every
//     crossing (per leaf, in the leaf's domain: domain_arrangement.h);
//  c) tessellate the domains of the leaves the cuts cross into pieces;
//  d) classify nodes with INCLUSION (box at inner nodes, base-triangle
//     barycentre at uncut leaves, a point inside each piece of a cut leaf) and
//     delete those on the removed side, propagating states up the tree;
//  e, f) the new boundary is the boundary of the kept region.
// Departure (e): instead of testing one point per trimming curve, boundaries
// are read off the kept pieces, so curves bounding deleted regions never appear.
// All cuts are computed against the leaf base triangles of both hierarchies,
// so the result converges to the exact trim as levels/lod grow.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "mesh/mesh.h"
#include "tbp/intersect_patches.h"
#include "tbp/point_in_solid.h"
#include "tbp/tbp_hierarchy.h"

namespace trimkit::tbp {

enum class Keep { kOutside, kInside };

struct TrimOptions {
    int levels = 2;  // hierarchy levels of target and tool (when built by trim_patch/trim_solid)
    int lod = 3;
    Keep keep = Keep::kOutside;  // the paper removes the part inside the solid (keep outside)
};

// One loop of the trimmed patch's boundary, counter-clockwise around the kept
// region in the (u, v) plane: uvw[k] -> uvw[k+1] (and last -> first).
struct TrimBoundary {
    std::vector<Eigen::Vector3d> uvw;     // root-domain parameters
    std::vector<Eigen::Vector3d> points;  // the patch at those parameters
    std::vector<char> on_cut;             // per edge: 1 on a trimming curve, 0 on the original boundary
};

// An untrimmed sub-TBP of the result: a hierarchy node kept whole, not below another kept node.
struct SubTbp {
    int level = 0, index = 0;
    std::array<Eigen::Vector3d, 3> domain;
    TbpPatch patch;
};

struct TrimStats {
    IntersectionStats intersection;  // phase a, summed over the solid's patches
    PointInSolidStats inclusion;     // phase d
    int cut_leaves = 0;              // leaves tessellated in phase c
    int pieces = 0;                  // pieces of cut leaves
    int kept_leaves = 0, deleted_leaves = 0;  // uncut leaves
    int boundary_segments = 0;       // edges of the new boundary on trimming curves
    double seconds = 0;
};

struct TrimResult {
    // The kept part: positions on the exact patch, exact normals, uvs = (u, v),
    // face ids `face_id`; welded; counter-clockwise like the patch.
    mesh::Mesh mesh;
    std::vector<TrimBoundary> boundaries;
    std::vector<SubTbp> untrimmed;
    std::vector<IntersectionComponent> curves;  // phase a components (all tool patches)
    TrimStats stats;
};

// Trims the patch of `target` against the closed solid whose hierarchies are `tool`.
TrimResult trim_patch(const TbpHierarchy& target, const std::vector<TbpHierarchy>& tool, Keep keep, int face_id = 0);

// Builds the hierarchies (options.levels, options.lod) and trims.
TrimResult trim_patch(const TbpPatch& target, const TbpSolid& tool, const TrimOptions& options);

// Every patch of `target` trimmed against `tool`; one welded mesh (face id =
// patch index), results per patch in `parts` if given.
mesh::Mesh trim_solid(const TbpSolid& target, const TbpSolid& tool, const TrimOptions& options,
                      std::vector<TrimResult>* parts = nullptr);

}  // namespace trimkit::tbp
