// The area a face's mesh loses inside its trim polygons: each triangle is flat
// where the surface over its (u,v) triangle is curved, so a mesh whose vertices lie
// on S is smaller than S over the same (u,v) region by about e / 3R of the area (a
// chord of sagitta e on a curve of radius R: 1 - sin(a)/a against
// (1 - cos(a)) / 3, for half-angle a). tessellate_model spends the tolerance on the
// cells (revolution_error), so a thin tube loses more of its area than the
// 0.2 % a check allows; it meshes such faces again with finer cells (area_budget.h).
// The trims' own loss is trim_area_loss.h's.
#pragma once

#include "geom/nurbs_surface.h"
#include "mesh/mesh.h"
#include "tess/surface_evaluator.h"

namespace trimkit::tess {

// Sum over the triangles of `face_mesh` (the mesh of one face of S, with uvs) of the
// area of S over the triangle's (u,v) triangle (three-point Gauss rule, exact for
// quadratic area elements) less the triangle's own area, in model units², less
// the lens between each face-boundary edge's 3D chord and S over its (u,v) chord
// (2/3 chord x sagitta, signed like the loss): trim_area_loss counts that lens, as
// part of the strip between the chord and the trim curve, and only finer trims
// close it. Positive when the mesh is smaller than the surface it spans.
double cell_area_loss(const geom::NurbsSurface& S, const mesh::Mesh& face_mesh);

// One triangle's share of that: the area of S over the (u,v) triangle `uv` (degree-2
// rule) less the area of the 3D triangle `xyz`.
double triangle_area_loss(SurfaceEvaluator& evaluator, const std::array<Eigen::Vector2d, 3>& uv,
                          const std::array<Eigen::Vector3d, 3>& xyz);

}  // namespace trimkit::tess
