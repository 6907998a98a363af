#include "tess/approximate_trim_curve.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "geom/error.h"
#include "geom/segment_distance.h"
#include "tess/derivative_bounds.h"
#include "geom/homogeneous_bezier.h"
#include "tess/lift_trim_curve.h"
#include "tess/simplify_trim_polyline.h"

namespace trimkit::tess {

using geom::bezier_piece;
using geom::de_casteljau;
using geom::project;
using geom::split_bezier;

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Homogeneous Bézier control points (w u, w v, w) of c over [t0, t1], one segment.
std::vector<Eigen::Vector3d> homogeneous_piece(const geom::NurbsCurve2d& c, double t0, double t1) {
    const geom::NurbsCurve2d sub = c.sub_curve(t0, t1);
    std::vector<Eigen::Vector3d> h(sub.points().size());
    for (size_t i = 0; i < h.size(); ++i) {
        const double w = sub.weights()[i];
        h[i] << w * sub.points()[i], w;
    }
    return h;
}

// [Balazs] Sec. 5.1: the distance of the curve from the chord P0 Pn, bounded by the
// largest distance d of the projected inner control points from the chord times
// sup_s of the inner rational basis sum (re-derived, replacing the paper's factor
// 1 - 2^(2-n)): C(s) = sum r_i P_i, and sum r_i x_i (x_i the chord point nearest
// P_i, x_0 = P0, x_n = Pn) lies on the chord, so dist <= d sup_s sum_{0<i<n} r_i(s).
// With A = sum_{0<i<n} w_i B_i <= w_in (1 - B_0 - B_n), E = w_0 B_0 + w_n B_n >=
// w_end (B_0 + B_n) and B_0 + B_n >= beta = 2^(1-n) (its minimum, at s = 1/2):
// A / (A + E) <= q (1 - beta) / (q (1 - beta) + beta), q = w_in / w_end. For a
// polynomial quadratic this is 1/2, the exact sagitta factor; a small circular arc
// gets w / (1 + w) ~ 1/2 too. Infinite if a weight is not positive.
double line_bound(const std::vector<Eigen::Vector4d>& P) {
    for (const auto& h : P)
        if (!(h.w() > 0.0)) return kInfinity;
    const Eigen::Vector3d a = project(P.front()), b = project(P.back());
    double e = 0.0, w_in = 0.0;
    for (size_t i = 1; i + 1 < P.size(); ++i) {
        e = std::max(e, geom::segment_distance(Eigen::Vector3d(project(P[i])), a, b));
        w_in = std::max(w_in, P[i].w());
    }
    if (e == 0.0) return 0.0;
    const int n = static_cast<int>(P.size()) - 1;
    const double beta = std::ldexp(1.0, 1 - n);
    const double q = w_in / std::min(P.front().w(), P.back().w());
    return e * q * (1.0 - beta) / (q * (1.0 - beta) + beta);
}

// Bound on max_s |c(s) - l(s)|, l(s) = b0 + s (bn - b0) the chord at the same s.
// c - l = N / W with N(s) = sum w_i B_i^n (b_i - b0) - s W(s) (bn - b0), degree n+1:
// N_k = (k/(n+1)) a_{k-1} + (1 - k/(n+1)) a_k - (k/(n+1)) w_{k-1} (bn - b0),
// a_i = w_i (b_i - b0) (degree elevation and s B_i^n = (i+1)/(n+1) B_{i+1}^{n+1};
// re-derived). |c - l| <= max |N_k| / min w_i.
double chord_parameter_bound(const std::vector<Eigen::Vector3d>& h) {
    const int n = static_cast<int>(h.size()) - 1;
    double w_min = kInfinity;
    for (const auto& x : h) w_min = std::min(w_min, x.z());
    if (!(w_min > 0.0)) return kInfinity;
    const Eigen::Vector2d b0 = project(h.front()), d = project(h.back()) - b0;
    auto a = [&](int i) -> Eigen::Vector2d {
        if (i < 0 || i > n) return Eigen::Vector2d::Zero();
        return h[i].head<2>() - h[i].z() * b0;
    };
    double e = 0.0;
    for (int k = 1; k <= n; ++k) {
        const double r = double(k) / (n + 1);
        const Eigen::Vector2d N = r * a(k - 1) + (1.0 - r) * a(k) - r * h[k - 1].z() * d;
        e = std::max(e, N.norm());
    }
    return e / w_min;
}

[[noreturn]] void throw_too_many_points() {
    throw geom::NumericalFailure("trim curve approximation needs more than " + std::to_string(kMaxTrimPoints) +
                                 " points (the curve is too long on its surface for the tolerance)");
}

// The projected control points of a part, or none when a weight is not positive (no
// convex hull property).
SegmentHull hull(const std::vector<Eigen::Vector4d>& P3, const std::vector<Eigen::Vector3d>& P2) {
    SegmentHull h;
    for (const auto& p : P3)
        if (!(p.w() > 0.0)) return {};
    for (const auto& p : P2)
        if (!(p.z() > 0.0)) return {};
    for (const auto& p : P3) h.xyz.push_back(project(p));
    for (const auto& p : P2) h.uv.push_back(project(p));
    return h;
}

// Midpoint subdivision of one lifted piece until each part's bound is within the
// budget. An explicit stack, not recursion: the depth reaches kMaxSubdivisionDepth
// on hostile curves, and under ASan every distinct recursive call stack of an
// allocation is stored (fuzz finding 11: 2 GB for a 2^19-piece curve).
struct Subdivider {
    double budget;       // γ·tol
    double speed;        // sqrt((M^u)² + (M^v)²) over the piece's region; 0 on an affine S
    std::size_t limit;   // most pieces accepted before the curve is given up
    mesh::Deadline* deadline;    // checked per part; nullptr: none
    std::vector<double>* s_out;  // right ends of accepted pieces, in order
    std::vector<SegmentHull>* hulls_out;  // and their control points

    struct Part {
        std::vector<Eigen::Vector4d> P3;
        std::vector<Eigen::Vector3d> P2;
        double sa, sb;
        int depth;
    };

    void run(const std::vector<Eigen::Vector4d>& P3, const std::vector<Eigen::Vector3d>& P2) {
        std::vector<Part> todo{{P3, P2, 0.0, 1.0, 0}};
        while (!todo.empty()) {
            Part part = std::move(todo.back());
            todo.pop_back();
            mesh::check_deadline(deadline, "trim curve approximation");
            // speed 0: no uv term (and no 0 x inf from a weight that is not positive).
            const double e = line_bound(part.P3) + (speed > 0.0 ? speed * chord_parameter_bound(part.P2) : 0.0);
            if (e <= budget || part.depth >= kMaxSubdivisionDepth) {
                if (s_out->size() >= limit) throw_too_many_points();
                s_out->push_back(part.sb);
                hulls_out->push_back(hull(part.P3, part.P2));
                continue;
            }
            const double sm = 0.5 * (part.sa + part.sb);
            Part left{{}, {}, part.sa, sm, part.depth + 1}, right{{}, {}, sm, part.sb, part.depth + 1};
            split_bezier(part.P3, 0.5, &left.P3, &right.P3);
            split_bezier(part.P2, 0.5, &left.P2, &right.P2);
            todo.push_back(std::move(right));  // the left half is taken first
            todo.push_back(std::move(left));
        }
    }
};

// [Yang] eq. 9-11: the number of uniform steps for c over [t0, t1].
long yang_steps(const geom::NurbsSurface& S, const geom::NurbsCurve2d& c, double t0, double t1,
                double tol) {
    const geom::NurbsCurve2d sub = c.sub_curve(t0, t1);
    const CurveDerivativeBounds Mc = curve_derivative_bounds(sub);
    const geom::NurbsCurve2d::Box box = sub.control_box();
    const SurfaceDerivativeBounds Ms =
        surface_derivative_bounds(S, Eigen::AlignedBox2d(box.min(), box.max()));
    const double M1 = (Ms.Mu + Ms.Mv) * Mc.Mtt / 8.0;
    const double M2 = (Ms.Muu * Mc.Mtu * Mc.Mtu + 2.0 * Ms.Muv * Mc.Mtu * Mc.Mtv +
                       Ms.Mvv * Mc.Mtv * Mc.Mtv) / 8.0;
    if (!(M1 + M2 > 0.0)) return 1;
    const double dt = std::sqrt(tol / (M1 + M2));
    return static_cast<long>(std::clamp(std::ceil((t1 - t0) / dt), 1.0, double(kMaxStepsPerPiece)));
}

// Appends c(t), S(c(t)) for t = t0 + (t1 - t0) s, s in `s_values` (ascending, s > 0);
// t0's point is expected to be present already.
void append_points(const geom::NurbsSurface& S, const geom::NurbsCurve2d& c, double t0, double t1,
                   const std::vector<double>& s_values, TrimPolyline* out, mesh::Deadline* deadline) {
    if (out->points.size() + s_values.size() > kMaxTrimPoints) throw_too_many_points();
    for (double s : s_values) {
        mesh::check_deadline(deadline, "trim curve approximation");
        PolylinePoint p;
        p.t = s >= 1.0 ? t1 : t0 + s * (t1 - t0);
        p.uv = c.evaluate(p.t);
        p.xyz = S.evaluate(p.uv.x(), p.uv.y());
        out->points.push_back(p);
    }
}

std::vector<double> uniform_steps(long n) {
    std::vector<double> s(n);
    for (long k = 1; k <= n; ++k) s[k - 1] = double(k) / n;
    return s;
}

}  // namespace

TrimPolyline approximate_trim_curve(const geom::NurbsSurface& S, const geom::NurbsCurve2d& c,
                                    double tolerance, TrimMethod method, mesh::Deadline* deadline,
                                    TrimSimplification simplification) {
    if (!std::isfinite(tolerance) || !(tolerance > 0.0))
        throw geom::InvalidInput("approximate_trim_curve: tolerance = " +
                                 geom::format_value(tolerance) + "; expected a finite value > 0");
    TrimPolyline out;
    const double ta = c.domain().first;
    append_points(S, c, ta, ta, {1.0}, &out, deadline);

    switch (method) {
    case TrimMethod::kBezier3d: {
        const double budget = kTrimGamma * tolerance;
        // An affine S maps the uv chord onto the 3D chord, so e_line bounds both.
        const bool affine = S.is_affine();
        std::vector<SegmentHull> hulls;  // per segment of `out`
        for (const LiftedPiece& piece : lift_trim_curve(S, c)) {
            mesh::check_deadline_now(deadline, "trim curve approximation");
            if (!piece.exact) {
                const long n = yang_steps(S, c, piece.t0, piece.t1, budget);
                append_points(S, c, piece.t0, piece.t1, uniform_steps(n), &out, deadline);
                hulls.resize(out.points.size() - 1);
                continue;
            }
            const std::vector<Eigen::Vector3d> P2 = homogeneous_piece(c, piece.t0, piece.t1);
            Eigen::AlignedBox2d box;
            for (const auto& h : P2) box.extend(project(h));
            const SurfaceDerivativeBounds Ms = surface_derivative_bounds(S, box);
            std::vector<double> s_values;
            const std::size_t limit = kMaxTrimPoints - out.points.size();
            const double speed = affine ? 0.0 : std::hypot(Ms.Mu, Ms.Mv);
            Subdivider{budget, speed, limit, deadline, &s_values, &hulls}.run(piece.P, P2);
            append_points(S, c, piece.t0, piece.t1, s_values, &out, deadline);
        }
        const geom::NurbsCurve2d::Box box = c.control_box();
        const SurfaceDerivativeBounds Ms =
            surface_derivative_bounds(S, Eigen::AlignedBox2d(box.min(), box.max()));
        const double speed = affine ? 0.0 : std::hypot(Ms.Mu, Ms.Mv);
        if (simplification == TrimSimplification::kHulls)
            simplify_trim_polyline(&out, hulls, S, tolerance, speed, deadline);
        else
            simplify_trim_polyline(&out, (1.0 - kTrimGamma) * tolerance, speed);
        break;
    }
    case TrimMethod::kYang: {
        const std::vector<double> breaks = trim_curve_breaks(S, c);
        for (size_t i = 0; i + 1 < breaks.size(); ++i) {
            const long n = yang_steps(S, c, breaks[i], breaks[i + 1], tolerance);
            append_points(S, c, breaks[i], breaks[i + 1], uniform_steps(n), &out, deadline);
        }
        break;
    }
    case TrimMethod::kParam: {
        for (const geom::NurbsCurve2d& seg : c.bezier_segments()) {
            const auto [t0, t1] = seg.domain();
            const double Mtt = curve_derivative_bounds(seg).Mtt;
            const long n = static_cast<long>(std::clamp(
                std::ceil((t1 - t0) * std::sqrt(Mtt / (8.0 * tolerance))), 1.0,
                double(kMaxStepsPerPiece)));
            append_points(S, c, t0, t1, uniform_steps(n), &out, deadline);
        }
        break;
    }
    }
    return out;
}

}  // namespace trimkit::tess
