// TriangleBvh: a bounding-volume hierarchy over the triangles of a mesh for
// closest-point queries (exact point-triangle distance). Axis-aligned boxes,
// median split on the longest axis of the centroids, at most kBvhLeafSize
// triangles per leaf. The mesh must outlive the tree and not change.
#pragma once

#include <cstdint>
#include <limits>
#include <vector>

#include <Eigen/Geometry>

#include "mesh/mesh.h"

namespace trimkit::tess {

constexpr int kBvhLeafSize = 4;

// Closest point to p on triangle (a, b, c), degenerate triangles included.
// [Ericson, Real-Time Collision Detection, Sec. 5.1.5] (Voronoi regions).
Eigen::Vector3d closest_point_on_triangle(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                                          const Eigen::Vector3d& b, const Eigen::Vector3d& c);

class TriangleBvh {
public:
    struct Hit {
        double distance = std::numeric_limits<double>::infinity();
        int triangle = -1;  // index into mesh.triangles, -1 if none within the limit
        Eigen::Vector3d point = Eigen::Vector3d::Zero();
    };

    explicit TriangleBvh(const mesh::Mesh& mesh);

    // The closest point of the mesh to x among points closer than max_distance.
    Hit closest(const Eigen::Vector3d& x,
                double max_distance = std::numeric_limits<double>::infinity()) const;

private:
    struct Node {
        Eigen::AlignedBox3d box;
        int first = 0, count = 0;  // leaf: range in order_; inner: count == 0
        int left = -1, right = -1;
    };
    int build(int first, int count, std::vector<Eigen::Vector3d>& centroids);

    const mesh::Mesh& mesh_;
    std::vector<int> order_;
    std::vector<Node> nodes_;
};

}  // namespace trimkit::tess
