#include "geom/bezier_triangle.h"

#include <cassert>
#include <cmath>
#include <string>

#include "geom/error.h"

namespace trimkit::geom {
namespace {

// One de Casteljau step ([Garcia] Sec. 2, [Sei89]), in place: the degree-m net
// `b` becomes the degree-(m-1) net b'_ijk = t0 b_{i+1,j,k} + t1 b_{i,j+1,k} + t2 b_{i,j,k+1}.
// With the storage order of BezierTriangle::index, b'_ijk lands where b_{i+1,j,k}
// was and reads only positions at or after it, so storage order (i, then j
// descending) is safe.
void casteljau_step(std::vector<Eigen::Vector3d>& b, int m, const Eigen::Vector3d& t) {
    for (int i = m - 1; i >= 0; --i)
        for (int j = m - 1 - i; j >= 0; --j) {
            const int p = BezierTriangle::index(m - 1, i, j);
            b[p] = t[0] * b[BezierTriangle::index(m, i + 1, j)] + t[1] * b[BezierTriangle::index(m, i, j + 1)] +
                   t[2] * b[BezierTriangle::index(m, i, j)];
        }
    b.resize(BezierTriangle::point_count(m - 1));
}

// Parameters within this distance of a degenerate point are moved towards the
// centre by this much to find a normal (relative to the unit domain).
constexpr double kNormalNudge = 1e-6;
// |db/du x db/dv| below this times the squared box diagonal counts as vanishing:
// rounding leaves ~1e-16 relative; 1e-14 keeps margin and is far below any real patch.
constexpr double kDegenerateNormalRelative = 1e-14;

}  // namespace

BezierTriangle::BezierTriangle(int degree, std::vector<Eigen::Vector3d> points) {
    if (degree < 1 || degree > kMaxBezierTriangleDegree)
        throw InvalidInput("BezierTriangle: degree " + std::to_string(degree) + "; expected 1 to " +
                           std::to_string(kMaxBezierTriangleDegree));
    if (static_cast<int>(points.size()) != point_count(degree))
        throw InvalidInput("BezierTriangle: " + std::to_string(points.size()) + " control points for degree " +
                           std::to_string(degree) + ", expected " + std::to_string(point_count(degree)));
    for (std::size_t q = 0; q < points.size(); ++q)
        if (!points[q].allFinite())
            throw InvalidInput("BezierTriangle: point[" + std::to_string(q) + "] = (" + format_value(points[q].x()) +
                               ", " + format_value(points[q].y()) + ", " + format_value(points[q].z()) +
                               "); coordinates must be finite");
    n_ = degree;
    b_ = std::move(points);
}

const Eigen::Vector3d& BezierTriangle::corner(int c) const {
    return c == 0 ? b_.front() : c == 1 ? b_[index(n_, 0, n_)] : b_.back();
}

Eigen::Vector3d BezierTriangle::evaluate(const Eigen::Vector3d& uvw) const {
    std::vector<Eigen::Vector3d> b = b_;
    for (int m = n_; m >= 1; --m) casteljau_step(b, m, uvw);
    return b[0];
}

Eigen::Vector3d BezierTriangle::blossom(const std::vector<Eigen::Vector3d>& args) const {
    assert(static_cast<int>(args.size()) == n_ && "blossom needs n arguments");
    std::vector<Eigen::Vector3d> b = b_;
    for (int m = n_; m >= 1; --m) casteljau_step(b, m, args[n_ - m]);
    return b[0];
}

Eigen::Vector3d BezierTriangle::derivative(const Eigen::Vector3d& uvw, const Eigen::Vector3d& d) const {
    // n-1 steps at uvw leave the linear net (b_100, b_010, b_001); the last step
    // taken with the direction d instead gives the derivative / n.
    std::vector<Eigen::Vector3d> b = b_;
    for (int m = n_; m >= 2; --m) casteljau_step(b, m, uvw);
    casteljau_step(b, 1, d);
    return n_ * b[0];
}

Eigen::Vector3d BezierTriangle::normal(const Eigen::Vector3d& uvw) const {
    const double scale = bounding_box().diagonal().norm();
    const double tiny = kDegenerateNormalRelative * scale * scale;
    Eigen::Vector3d p = uvw;
    for (int attempt = 0; attempt < 3; ++attempt) {
        const Eigen::Vector3d c = derivative_u(p).cross(derivative_v(p));
        if (c.norm() > tiny) return c.normalized();
        const double step = kNormalNudge * std::pow(100.0, attempt);
        p = (1 - step) * p + step * Eigen::Vector3d::Constant(1.0 / 3.0);
    }
    throw NumericalFailure("BezierTriangle: no normal at (u,v,w) = (" + format_value(uvw[0]) + ", " +
                           format_value(uvw[1]) + ", " + format_value(uvw[2]) + "); the patch is degenerate there");
}

BezierTriangle BezierTriangle::subpatch(const Eigen::Vector3d& r, const Eigen::Vector3d& s,
                                        const Eigen::Vector3d& t) const {
    std::vector<Eigen::Vector3d> c(b_.size());
    std::vector<Eigen::Vector3d> a = b_;  // r applied i times: degree n - i
    for (int i = 0; i <= n_; ++i) {
        if (i > 0) casteljau_step(a, n_ - i + 1, r);
        std::vector<Eigen::Vector3d> bs = a;  // then s applied j times: degree n - i - j
        for (int j = 0; j <= n_ - i; ++j) {
            if (j > 0) casteljau_step(bs, n_ - i - j + 1, s);
            std::vector<Eigen::Vector3d> bt = bs;  // then t applied k = n-i-j times: a point
            for (int m = n_ - i - j; m >= 1; --m) casteljau_step(bt, m, t);
            c[index(n_, i, j)] = bt[0];
        }
    }
    BezierTriangle out;
    out.n_ = n_;
    out.b_ = std::move(c);
    return out;
}

Eigen::AlignedBox3d BezierTriangle::bounding_box() const {
    Eigen::AlignedBox3d box;
    for (const auto& p : b_) box.extend(p);
    return box;
}

}  // namespace trimkit::geom
