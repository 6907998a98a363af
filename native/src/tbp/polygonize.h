// Polygonization of TBPs ([Garcia] Sec. 3, "Polygonization"): the mesh of a
// patch at hierarchy level L and lod K is the triangle pattern with rate
// N = (K+1)^L segments per edge, i.e. the base triangles of the level-L nodes,
// with vertices on the exact surface. The triangle-domain pattern comes from
// OpenSubdiv's Bfr::Tessellation (a Loop/triangle Parameterization; its corners
// 0, 1, 2 are the patch's corners u, v, w) when trimkit is built with
// OpenSubdiv, else from an equivalent uniform pattern of our own. All patches of
// a solid use the same rate, so a shared edge gets the same points from both
// sides and the welded mesh is watertight.
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>

#include "mesh/mesh.h"
#include "tbp/tbp_solid.h"

namespace trimkit::tbp {

struct PolygonizeOptions {
    int level = 2;  // hierarchy level L >= 0
    int lod = 3;    // subdivision level of detail K >= 0: N = (K+1)^L, at most kMaxPolygonizeRate
    // Weld vertices of neighbouring patches (tolerance kWeldRelativeTolerance x the solid's box diagonal).
    bool weld = true;
    // When welding, keep vertices whose exact normals differ by more than 1e-3 rad apart (creases).
    bool keep_split_normals = false;
};

// Largest pattern rate (segments per edge) polygonize accepts.
constexpr int kMaxPolygonizeRate = 4096;
// Shared-edge points of neighbouring patches differ by rounding only (~1e-16
// relative); 1e-9 of the model size welds them and nothing else.
constexpr double kWeldRelativeTolerance = 1e-9;

// The rate N = (lod+1)^level; throws InvalidInput if level or lod < 0 or N > kMaxPolygonizeRate.
int polygonize_rate(int level, int lod);

// The triangle-domain pattern with `rate` segments per edge: barycentric
// (u,v,w) points, exact multiples of 1/rate (the boundary first, from corner
// u = 1 through v = 1 and w = 1, then the interior), and triangles
// counter-clockwise in the (u, v) plane.
struct DomainPattern {
    std::vector<Eigen::Vector3d> points;
    std::vector<std::array<int, 3>> triangles;
};
DomainPattern triangle_pattern(int rate);

// Mesh of one patch: positions b(u,v,w), exact unit normals, uvs = (u, v),
// face ids `face_id`. Not welded (pattern points are distinct).
mesh::Mesh polygonize_patch(const TbpPatch& patch, int rate, int face_id = 0);

// Mesh of a solid: every patch at the same rate, face id = patch index, welded
// unless options.weld is false. Validates the solid; a patch with no normal even
// near a point of the pattern (no area there) is InvalidInput naming the patch.
mesh::Mesh polygonize(const TbpSolid& solid, const PolygonizeOptions& options);

}  // namespace trimkit::tbp
