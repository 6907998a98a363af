// Intersection segment of two triangles in 3D, after Moller's interval test
// ([Mol97], cited as TR_INT in [Garcia] Alg. 4.1): each triangle meets the
// other's plane in an interval of the planes' common line; the segment is the
// overlap of the two intervals. Coplanar pairs report no segment (they bound
// no curve); touching in a single point reports none either.
#pragma once

#include <array>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace trimkit::tbp {

using Triangle3 = std::array<Eigen::Vector3d, 3>;

// Signed distances below this fraction of the triangle's size count as zero
// (vertex on the other plane): double rounding of a cross and dot product is
// ~1e-16 relative; 1e-13 leaves margin and is far below any feature.
constexpr double kPlaneRelativeTolerance = 1e-13;

// True and the segment's ends in `p`, `q` (distinct points) if t1 and t2 cross
// along a segment of positive length. Degenerate triangles (zero area) never do.
bool triangle_intersection(const Triangle3& t1, const Triangle3& t2, Eigen::Vector3d& p, Eigen::Vector3d& q);

// Barycentric coordinates (of corners 0, 1, 2) of the point of t's plane
// nearest to x; small negative values from rounding are clamped to 0 and the
// result renormalised to sum 1.
Eigen::Vector3d barycentric(const Triangle3& t, const Eigen::Vector3d& x);

}  // namespace trimkit::tbp
