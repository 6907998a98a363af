// TrimRegion: the trimmed (u,v) domain of a face for measuring it, with its
// loops sampled finely as closed polygons. Membership is by the even-odd rule
// (a point is inside when a ray in +u crosses the loops an odd number of times),
// so loop orientation does not matter. Horizontal scanlines give the inside
// intervals of a row of samples at once; segments are bucketed by v so a
// scanline touches only the segments that can cross it.
#pragma once

#include <vector>

#include <Eigen/Geometry>

#include "geom/face.h"

namespace trimkit::tess {

struct TrimRegionOptions {
    // Polygon points per Bézier span of each coedge curve (at least
    // kMinCoedgeSamples per coedge). The area error of the polygon against the
    // curve falls as 1/n²: a circle of 4 quadratic spans at 256 per span is
    // 1024-gon, 6e-6 relative low (2π²/(3n²)); 32 per span would be 4e-4.
    int samples_per_span = 256;
};

constexpr int kMinCoedgeSamples = 16;

class TrimRegion {
public:
    // Throws geom::InvalidInput if the face has no loop with at least 3 points.
    explicit TrimRegion(const geom::Face& face, const TrimRegionOptions& options = {});

    // Each loop as a closed polygon (the last point is not repeated).
    const std::vector<std::vector<Eigen::Vector2d>>& loops() const { return loops_; }
    // Parameters of the loops' first points of their coedges: the corners, where the
    // boundary may turn sharply.
    const std::vector<Eigen::Vector2d>& corners() const { return corners_; }
    // Bounding box of the loops, clipped to the surface's domain.
    const Eigen::AlignedBox2d& box() const { return box_; }

    bool contains(const Eigen::Vector2d& uv) const;
    // The u at which the loops cross the line v = const, sorted; [x0, x1], [x2, x3],
    // ... are inside. Vertices exactly on the line count on the side v' > v.
    std::vector<double> crossings(double v) const;

private:
    struct Segment {
        Eigen::Vector2d a, b;
    };
    std::vector<std::vector<Eigen::Vector2d>> loops_;
    std::vector<Eigen::Vector2d> corners_;
    Eigen::AlignedBox2d box_;
    std::vector<Segment> segments_;
    std::vector<std::vector<int>> bins_;  // segment indices per v bin
    double bin_v0_ = 0.0, bin_h_ = 1.0;
};

// Area of the face's surface over the region, ∫∫ |Su × Sv| du dv. Rows of a grid
// whose lines include the knots and corners: rows no loop crosses get 4-point
// Gauss-Legendre in v, crossed rows 2^levels sub-rows of 2-point Gauss; on each
// Gauss line the inside intervals (exact for the polygons) are split at the u
// grid lines and integrated with 4-point Gauss. The error is dominated by the
// polygon approximation of the trim curves (see TrimRegionOptions) and by points
// where a trim curve is tangent to v = const; it is ~1e-10 relative when the
// trims follow iso-lines; a disc of radius 0.3 comes out 3e-5 relative high.
double trimmed_area(const geom::NurbsSurface& surface, const TrimRegion& region, int cells = 24,
                    int levels = 2);

}  // namespace trimkit::tess
