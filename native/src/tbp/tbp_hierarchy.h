// TbpHierarchy: the levels-of-detail tree of one patch ([Garcia] Sec. 3). Level 0
// is the whole patch; every node of level l < levels is split into (lod+1)^2
// subpatches at level l+1 (the uniform split of its triangle into (lod+1)^2
// subtriangles, alternately "up" and "down"), so level L holds (lod+1)^(2L)
// nodes (n_SP of the paper at L = levels). Each node stores its subdomain (three
// barycentric corners in the root patch's (u,v,w) domain, oriented like the
// root), its control points (a geom::BezierTriangle) and their bounding box.
// Children of node k at level l are nodes k*(lod+1)^2 ... k*(lod+1)^2 + (lod+1)^2 - 1
// at level l+1. Built once, reused by polygonization, intersection,
// point-in-solid and trimming.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "tbp/tbp_solid.h"

namespace trimkit::tbp {

// A hierarchy may hold at most this many leaves (levels=4, lod=7 gives 16.7
// million; memory for cubics ~ 300 bytes a node).
constexpr long long kMaxHierarchyLeaves = 1ll << 22;

struct TbpNode {
    std::array<Eigen::Vector3d, 3> domain;  // corners (u,v,w) in the root domain: roles u, v, w
    geom::BezierTriangle patch;             // the subpatch over `domain`
    Eigen::AlignedBox3d box;                // box of patch's control points

    // Corner c of the base triangle (the subpatch's corner control points).
    const Eigen::Vector3d& base(int c) const { return patch.corner(c); }
    // Root-domain (u,v,w) of local barycentric coordinates `local` in this node.
    Eigen::Vector3d root_parameter(const Eigen::Vector3d& local) const {
        return local[0] * domain[0] + local[1] * domain[1] + local[2] * domain[2];
    }
};

// The m^2 subtriangles of the unit triangle cut into m parts per edge, as
// barycentric corners (roles u, v, w, same orientation as the parent): the
// "up" triangles are translated copies of the parent, the "down" ones rotated
// by 180 degrees. Order: rows of constant v = b/m from b = 0, within a row up
// and down alternately along u.
std::vector<std::array<Eigen::Vector3d, 3>> uniform_subtriangles(int m);

class TbpHierarchy {
public:
    // Throws InvalidInput if levels < 0, lod < 0 or the hierarchy would have more
    // than kMaxHierarchyLeaves leaves.
    TbpHierarchy(TbpPatch patch, int levels, int lod);

    int levels() const { return levels_; }
    int lod() const { return lod_; }
    int split() const { return lod_ + 1; }                      // m: subdivisions per edge per level
    int children_per_node() const { return split() * split(); }  // m^2
    const TbpPatch& patch() const { return levels_data_[0][0].patch; }

    // Nodes of level l in [0, levels()].
    const std::vector<TbpNode>& level(int l) const { return levels_data_[l]; }
    const TbpNode& node(int l, int k) const { return levels_data_[l][k]; }
    const std::vector<TbpNode>& leaves() const { return levels_data_.back(); }
    int first_child(int k) const { return k * children_per_node(); }
    int parent(int k) const { return k / children_per_node(); }

private:
    int levels_, lod_;
    std::vector<std::vector<TbpNode>> levels_data_;
};

// One hierarchy per patch of `solid` (validated first).
std::vector<TbpHierarchy> build_hierarchies(const TbpSolid& solid, int levels, int lod);

}  // namespace trimkit::tbp
