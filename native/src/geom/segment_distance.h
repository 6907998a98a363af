// Distance from a point to a segment, in any dimension (Eigen fixed-size vectors).
#pragma once

#include <algorithm>

namespace trimkit::geom {

// |x - nearest point of segment a b|; a degenerate segment is its point a.
template <class V>
double segment_distance(const V& x, const V& a, const V& b) {
    const V ab = b - a;
    const double len2 = ab.squaredNorm();
    const double lambda = len2 > 0.0 ? std::clamp((x - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    return (x - (a + lambda * ab)).norm();
}

}  // namespace trimkit::geom
