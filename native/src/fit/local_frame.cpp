#include "fit/local_frame.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>

#include "geom/error.h"

namespace trimkit::fit {
namespace {

// Below this ratio of the second to the first principal extent the boundary is
// a line (or a point) and no reference plane can be chosen.
constexpr double kFlatBoundary = 1e-9;

// Spacing weight of sample k: half the distance to its neighbours on the loop.
std::vector<double> spacing(const std::vector<BoundarySample>& s) {
    std::vector<double> w(s.size(), 0.0);
    for (std::size_t k = 0; k < s.size(); ++k) {
        std::size_t first = k, last = k;
        while (first > 0 && s[first - 1].loop == s[k].loop) --first;
        while (last + 1 < s.size() && s[last + 1].loop == s[k].loop) ++last;
        const std::size_t next = k == last ? first : k + 1, prev = k == first ? last : k - 1;
        w[k] = 0.5 * ((s[next].x - s[k].x).norm() + (s[k].x - s[prev].x).norm());
    }
    return w;
}

}  // namespace

Eigen::Vector2d LocalFrame::plane(const Eigen::Vector3d& p) const {
    return {e1.dot(p - origin), e2.dot(p - origin)};
}

Eigen::Vector2d LocalFrame::uv(const Eigen::Vector3d& p) const {
    const Eigen::Vector2d q = plane(p);
    return {(q.x() - x0) / (x1 - x0), (q.y() - y0) / (y1 - y0)};
}

LocalFrame local_frame(const std::vector<BoundarySample>& samples, int outer_loop) {
    const std::vector<double> w = spacing(samples);
    double total = 0;
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (std::size_t k = 0; k < samples.size(); ++k) {
        c += w[k] * samples[k].x;
        total += w[k];
    }
    if (!(total > 0)) throw geom::NumericalFailure("local_frame: the boundary has no length");
    c /= total;
    Eigen::Matrix3d C = Eigen::Matrix3d::Zero();
    for (std::size_t k = 0; k < samples.size(); ++k) C += w[k] * (samples[k].x - c) * (samples[k].x - c).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(C / total);
    const Eigen::Vector3d lambda = eigen.eigenvalues();  // ascending
    if (!(lambda[1] > kFlatBoundary * kFlatBoundary * lambda[2]))
        throw geom::NumericalFailure("local_frame: the boundary lies on a line");
    LocalFrame f;
    f.origin = c;
    f.e1 = eigen.eigenvectors().col(2);
    f.e2 = eigen.eigenvectors().col(1);
    // Orientation: the outer loop's signed area about n must be positive.
    double area = 0;
    std::vector<Eigen::Vector2d> outer;
    for (const BoundarySample& s : samples)
        if (s.loop == outer_loop) outer.push_back({f.e1.dot(s.x - c), f.e2.dot(s.x - c)});
    if (outer.empty()) throw geom::NumericalFailure("local_frame: the outer loop has no samples");
    for (std::size_t i = 0; i < outer.size(); ++i) {
        const Eigen::Vector2d& a = outer[i];
        const Eigen::Vector2d& b = outer[(i + 1) % outer.size()];
        area += a.x() * b.y() - a.y() * b.x();
    }
    if (area < 0) f.e2 = -f.e2;
    f.n = f.e1.cross(f.e2).normalized();
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const BoundarySample& s : samples) {
        const Eigen::Vector2d q = f.plane(s.x);
        x0 = std::min(x0, q.x()), x1 = std::max(x1, q.x()), y0 = std::min(y0, q.y()), y1 = std::max(y1, q.y());
    }
    const double margin = kReferenceMargin * std::max(x1 - x0, y1 - y0);
    f.x0 = x0 - margin, f.x1 = x1 + margin, f.y0 = y0 - margin, f.y1 = y1 + margin;
    return f;
}

}  // namespace trimkit::fit
