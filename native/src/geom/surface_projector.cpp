#include "geom/surface_projector.h"

#include <algorithm>
#include <cmath>

#include "geom/error.h"

namespace trimkit::geom {
namespace {

// Newton stops when the step moves the surface point less than this fraction
// of the surface size (1e-12: at double precision's useful limit).
constexpr double kNewtonStep = 1e-12;
constexpr int kNewtonIterations = 40;
// A foot this close (fraction of the surface's size) to the point is found: invert
// tries no further starts. Points that close are on the surface up to a file's
// sewing gap or a mesh's tolerance, where the foot continuity gives is the one
// wanted (a sewn corner 9e-5 off a sphere's pole: its nearest foot lies at another
// longitude); the further starts are for feet clearly missed (15 mm from a pole on
// a sphere of radius 110, 2.35 on a spindle torus of size 200).
constexpr double kFootFound = 1e-4;
// Two surface boundaries closer than this fraction of the size make the
// direction closed (a seam); 1e-7 is above file rounding, below real gaps.
constexpr double kSeamRelative = 1e-7;
// A point within this fraction of the domain from a seam may sit on either side.
constexpr double kSeamZone = 1e-6;
// Grid samples per direction: enough to start Newton in the right basin on
// CAD surfaces with a few knot spans, bounded to keep projection cheap.
constexpr int kMinGrid = 9, kMaxGrid = 41;
// Samples of a model-space curve per knot span and overall.
constexpr int kSamplesPerSpan = 16;
constexpr int kMaxSamples = 2000;

int grid_count(const std::vector<double>& U, int p) {
    int spans = 0;
    for (std::size_t i = 1; i < U.size(); ++i)
        if (U[i] > U[i - 1]) ++spans;
    return std::clamp(4 * spans * std::max(1, p - 1) + 1, kMinGrid, kMaxGrid);
}

}  // namespace

SurfaceProjector::SurfaceProjector(const NurbsSurface& s) : s_(s) {
    std::tie(u0_, u1_) = s.domain_u();
    std::tie(v0_, v1_) = s.domain_v();
    nu_ = grid_count(s.knots_u(), s.degree_u());
    nv_ = grid_count(s.knots_v(), s.degree_v());
    grid_.resize(static_cast<std::size_t>(nu_) * nv_);
    for (int i = 0; i < nu_; ++i)
        for (int j = 0; j < nv_; ++j)
            grid_[i * nv_ + j] = s.evaluate(u0_ + (u1_ - u0_) * i / (nu_ - 1),
                                            v0_ + (v1_ - v0_) * j / (nv_ - 1));
    Eigen::AlignedBox3d box;
    for (const auto& p : grid_) box.extend(p);
    size_ = std::max(box.diagonal().norm(), 1e-300);
    mark_poles();
    const double tol = kSeamRelative * size_;
    closed_u_ = closed_v_ = true;
    for (int j = 0; j < nv_; ++j)
        if ((grid_[j] - grid_[(nu_ - 1) * nv_ + j]).norm() > tol) closed_u_ = false;
    for (int i = 0; i < nu_; ++i)
        if ((grid_[i * nv_] - grid_[i * nv_ + nv_ - 1]).norm() > tol) closed_v_ = false;
}

void SurfaceProjector::mark_poles() {
    const double same = kSameFoot * size_;
    at_pole_.assign(grid_.size(), 0);
    for (int j = 0; j < nv_; ++j) {
        bool one_point = true;
        for (int i = 1; i < nu_ && one_point; ++i) one_point = (grid_[i * nv_ + j] - grid_[j]).norm() <= same;
        for (int i = 0; i < nu_ && one_point; ++i) at_pole_[i * nv_ + j] = 1;
    }
    for (int i = 0; i < nu_; ++i) {
        bool one_point = true;
        for (int j = 1; j < nv_ && one_point; ++j) one_point = (grid_[i * nv_ + j] - grid_[i * nv_]).norm() <= same;
        for (int j = 0; j < nv_ && one_point; ++j) at_pole_[i * nv_ + j] = 1;
    }
}

Eigen::Vector2d SurfaceProjector::grid_uv(int k) const {
    const int i = k / nv_, j = k % nv_;
    return {u0_ + (u1_ - u0_) * i / (nu_ - 1), v0_ + (v1_ - v0_) * j / (nv_ - 1)};
}

Eigen::Vector2d SurfaceProjector::newton(const Eigen::Vector3d& x, Eigen::Vector2d uv) const {
    for (int it = 0; it < kNewtonIterations; ++it) {
        SurfaceDerivatives d;
        try {
            d = s_.derivatives(uv.x(), uv.y());
        } catch (const NumericalFailure&) {
            break;
        }
        const Eigen::Vector3d r = d.S - x;
        const Eigen::Vector2d f(d.Su.dot(r), d.Sv.dot(r));
        Eigen::Matrix2d J;
        J << d.Su.squaredNorm() + r.dot(d.Suu), d.Su.dot(d.Sv) + r.dot(d.Suv),
            d.Su.dot(d.Sv) + r.dot(d.Suv), d.Sv.squaredNorm() + r.dot(d.Svv);
        // Levenberg-style damping keeps the step finite at poles and folds.
        const double damp = 1e-12 * (J.diagonal().cwiseAbs().maxCoeff() + 1e-300);
        J(0, 0) += damp;
        J(1, 1) += damp;
        Eigen::Vector2d step = J.fullPivLu().solve(-f);
        if (!step.allFinite()) break;
        Eigen::Vector2d next = uv + step;
        next.x() = std::clamp(next.x(), u0_, u1_);
        next.y() = std::clamp(next.y(), v0_, v1_);
        const Eigen::Vector2d moved = next - uv;
        uv = next;
        if ((d.Su * moved.x() + d.Sv * moved.y()).norm() <= kNewtonStep * size_) break;
    }
    return uv;
}

bool SurfaceProjector::grid_neighbours(int a, int b) const {
    int di = std::abs(a / nv_ - b / nv_), dj = std::abs(a % nv_ - b % nv_);
    if (closed_u_) di = std::min(di, nu_ - 1 - di);
    if (closed_v_) dj = std::min(dj, nv_ - 1 - dj);
    return di <= 1 && dj <= 1;
}

Eigen::Vector2d SurfaceProjector::invert(const Eigen::Vector3d& x, const Eigen::Vector2d* near) const {
    int best = 0;
    double bd = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < grid_.size(); ++k) {
        const double d = (grid_[k] - x).squaredNorm();
        if (d < bd) bd = d, best = static_cast<int>(k);
    }
    Eigen::Vector2d uv = newton(x, grid_uv(best));
    double du = (s_.evaluate(uv.x(), uv.y()) - x).norm();
    if (du <= kFootFound * size_) return settled(x, uv, du, near);
    // Newton also starts from the nearest sample off a pole (at a pole the free
    // parameter's derivative is zero: Newton cannot turn towards x's side) and
    // from the nearest one beyond best's neighbours (a surface folded near
    // itself, as a spindle torus by its axis: the nearest sample may lie in
    // another basin than the foot). The nearest foot wins; ties keep the first.
    int off_pole = -1, far = -1;
    double bo = std::numeric_limits<double>::infinity(), bf = bo;
    for (std::size_t k = 0; k < grid_.size(); ++k) {
        if (at_pole_[k]) continue;
        const double d = (grid_[k] - x).squaredNorm();
        if (d < bo) bo = d, off_pole = static_cast<int>(k);
        if (d < bf && !grid_neighbours(best, static_cast<int>(k))) bf = d, far = static_cast<int>(k);
    }
    for (int start : {at_pole_[best] ? off_pole : -1, far}) {
        if (start < 0) continue;
        const Eigen::Vector2d alt = newton(x, grid_uv(start));
        const double da = (s_.evaluate(alt.x(), alt.y()) - x).norm();
        if (da < du - kSameFoot * size_) uv = alt, du = da;
    }
    return settled(x, uv, du, near);
}

Eigen::Vector2d SurfaceProjector::settled(const Eigen::Vector3d& x, Eigen::Vector2d uv, double du,
                                          const Eigen::Vector2d* near) const {
    if (near) {
        Eigen::Vector2d alt = newton(x, *near);
        const double da = (s_.evaluate(alt.x(), alt.y()) - x).norm();
        // Prefer continuity with the previous point unless clearly worse (a point
        // a hair off a pole, as a file's vertex often is, has a foot at any u).
        if (da <= du + kSameFoot * size_) {
            uv = alt;
            du = da;
        }
        const double zu = kSeamZone * (u1_ - u0_), zv = kSeamZone * (v1_ - v0_);
        if (closed_u_) {
            if (uv.x() - u0_ < zu && u1_ - near->x() < near->x() - u0_) uv.x() = u1_;
            else if (u1_ - uv.x() < zu && near->x() - u0_ < u1_ - near->x()) uv.x() = u0_;
        }
        if (closed_v_) {
            if (uv.y() - v0_ < zv && v1_ - near->y() < near->y() - v0_) uv.y() = v1_;
            else if (v1_ - uv.y() < zv && near->y() - v0_ < v1_ - near->y()) uv.y() = v0_;
        }
        // At a pole (a degenerate boundary) one parameter is free: keep near's.
        if (free_at(uv, 0)) uv.x() = near->x();
        if (free_at(uv, 1)) uv.y() = near->y();
    }
    return uv;
}

bool parameter_is_free(const NurbsSurface& s, const Eigen::Vector2d& uv, int d, double size) {
    try {
        const SurfaceDerivatives D = s.derivatives(uv.x(), uv.y());
        const double along = (d == 0 ? D.Su : D.Sv).norm(), across = (d == 0 ? D.Sv : D.Su).norm();
        const auto [lo, hi] = d == 0 ? s.domain_u() : s.domain_v();
        return along * (hi - lo) < kSameFoot * size && along < 1e-3 * across;
    } catch (const NumericalFailure&) {
        return false;
    }
}

namespace {

// Exact inverse for a degree-1 x 1, 2 x 2, non-rational surface whose corners
// form a parallelogram (planes from IGES 108/190 and planar B-splines).
std::optional<NurbsCurve2d> affine_inverse(const NurbsSurface& s,
                                                 const NurbsCurve3d& c) {
    if (s.degree_u() != 1 || s.degree_v() != 1 || s.count_u() != 2 || s.count_v() != 2 ||
        s.is_rational())
        return std::nullopt;
    const Eigen::Vector3d P00 = s.point(0, 0), P10 = s.point(1, 0), P01 = s.point(0, 1),
                          P11 = s.point(1, 1);
    const Eigen::Vector3d eu = P10 - P00, ev = P01 - P00;
    const double size = std::max(eu.norm(), ev.norm());
    if (!(size > 0) || (P11 - P10 - ev).norm() > 1e-12 * size) return std::nullopt;
    const auto [u0, u1] = s.domain_u();
    const auto [v0, v1] = s.domain_v();
    Eigen::Matrix<double, 3, 2> A;
    A << eu, ev;
    const Eigen::Matrix2d G = A.transpose() * A;
    if (std::fabs(G.determinant()) < 1e-24 * size * size * size * size) return std::nullopt;
    const Eigen::Matrix2d Gi = G.inverse();
    std::vector<Eigen::Vector2d> q;
    q.reserve(c.points().size());
    for (const Eigen::Vector3d& p : c.points()) {
        Eigen::Vector2d ab = Gi * (A.transpose() * (p - P00));
        q.emplace_back(u0 + ab.x() * (u1 - u0), v0 + ab.y() * (v1 - v0));
    }
    return NurbsCurve2d(c.degree(), c.knots(), std::move(q), c.weights());
}

// Points at a pole have a free parameter (any value is the same point): each takes
// it from the nearest point of the curve off the pole, so the curve reaches the
// pole along its own iso-line instead of jumping to an arbitrary one.
void settle_free_parameters(const SurfaceProjector& projector, std::vector<Eigen::Vector2d>* points) {
    std::vector<Eigen::Vector2d>& uv = *points;
    const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(uv.size());
    for (int d = 0; d < 2; ++d) {
        std::vector<char> free(uv.size());
        for (std::ptrdiff_t k = 0; k < n; ++k) free[k] = projector.free_at(uv[k], d);
        for (std::ptrdiff_t k = 0; k < n; ++k) {
            if (!free[k]) continue;
            for (std::ptrdiff_t step = 1; step < n; ++step) {
                const std::ptrdiff_t j = k - step >= 0 && !free[k - step] ? k - step
                                         : k + step < n && !free[k + step] ? k + step : -1;
                if (j < 0) continue;
                uv[k][d] = uv[j][d];
                break;
            }
        }
    }
}

}  // namespace

NurbsCurve2d project_curve(const SurfaceProjector& projector, const NurbsCurve3d& c,
                                 double* max_distance) {
    const NurbsSurface& s = projector.surface();
    if (auto exact = affine_inverse(s, c)) {
        if (max_distance) {
            double m = 0;
            for (const auto& p : c.points()) {
                Eigen::Vector2d uv = projector.invert(p);
                m = std::max(m, (s.evaluate(uv.x(), uv.y()) - p).norm());
            }
            *max_distance = m;
        }
        return *exact;
    }
    // Parameters: kSamplesPerSpan per non-empty knot span of c.
    const std::vector<double>& U = c.knots();
    const int p = c.degree();
    const auto [a, b] = c.domain();
    std::vector<double> breaks;
    for (std::size_t i = p; i + p < U.size(); ++i)
        if (U[i] >= a && U[i] <= b && (breaks.empty() || U[i] > breaks.back())) breaks.push_back(U[i]);
    if (breaks.size() < 2) breaks = {a, b};
    const int spans = static_cast<int>(breaks.size()) - 1;
    const int per = std::max(2, std::min(kSamplesPerSpan, kMaxSamples / std::max(1, spans)));
    std::vector<double> t;
    for (int k = 0; k < spans; ++k)
        for (int j = 0; j < per; ++j) t.push_back(breaks[k] + (breaks[k + 1] - breaks[k]) * j / per);
    t.push_back(b);
    std::vector<Eigen::Vector2d> uv(t.size());
    std::vector<Eigen::Vector3d> x(t.size());
    double dmax = 0;
    for (std::size_t k = 0; k < t.size(); ++k) {
        x[k] = c.evaluate(t[k]);
        uv[k] = projector.invert(x[k], k > 0 ? &uv[k - 1] : nullptr);
    }
    // The first point had no neighbour to settle a seam or pole: redo it from the second.
    if (uv.size() > 1) uv[0] = projector.invert(x[0], &uv[1]);
    settle_free_parameters(projector, &uv);
    for (std::size_t k = 0; k < t.size(); ++k)
        dmax = std::max(dmax, (s.evaluate(uv[k].x(), uv[k].y()) - x[k]).norm());
    if (max_distance) *max_distance = dmax;
    std::vector<double> knots;
    knots.reserve(t.size() + 2);
    knots.push_back(t.front());
    knots.insert(knots.end(), t.begin(), t.end());
    knots.push_back(t.back());
    return NurbsCurve2d(1, std::move(knots), std::move(uv));
}

}  // namespace trimkit::geom
