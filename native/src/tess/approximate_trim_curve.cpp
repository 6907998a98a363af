#include "tess/approximate_trim_curve.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "geom/error.h"
#include "tess/derivative_bounds.h"
#include "tess/homogeneous_bezier.h"
#include "tess/lift_trim_curve.h"
#include "tess/simplify_trim_polyline.h"

namespace trimkit::tess {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Most equal pieces one subdivision step cuts a lifted piece into.
constexpr int kMaxPlannedPieces = 64;

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
    const Eigen::Vector3d a = project(P.front()), b = project(P.back()), ab = b - a;
    const double len2 = ab.squaredNorm();
    double e = 0.0, w_in = 0.0;
    for (size_t i = 1; i + 1 < P.size(); ++i) {
        const Eigen::Vector3d x = project(P[i]);
        const double lambda = len2 > 0.0 ? std::clamp((x - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
        e = std::max(e, (x - a - lambda * ab).norm());
        w_in = std::max(w_in, P[i].w());
    }
    if (e == 0.0) return 0.0;
    const int n = static_cast<int>(P.size()) - 1;
    const double beta = std::ldexp(1.0, 1 - n);
    const double q = w_in / std::min(P.front().w(), P.back().w());
    return e * q * (1.0 - beta) / (q * (1.0 - beta) + beta);
}

// Bound F/8 on |S(l(s)) - chord(s)|, the 3D chord's distance from S over the uv
// chord l: f(s) = S(l(s)) has |f''| <= F = M^uu du^2 + 2 M^uv |du dv| + M^vv dv^2
// ([Yang] eq. 10 with a linear curve) and the chord interpolates f at s = 0, 1, so
// |f - chord| <= s (1 - s) F / 2 <= F / 8. The uv chord lies in the hull of the
// piece's control points, inside the box the M's were taken over.
double chord_sag_bound(const std::vector<Eigen::Vector3d>& P2, const SurfaceDerivativeBounds& M) {
    const Eigen::Vector2d d = project(P2.back()) - project(P2.front());
    const double du = std::abs(d.x()), dv = std::abs(d.y());
    return (M.Muu * du * du + 2.0 * M.Muv * du * dv + M.Mvv * dv * dv) / 8.0;
}

// The error of one accepted piece (re-derived; departs from the sum e_line + e_uv
// of earlier versions, which counts the plane's sagitta twice):
//  - the 3D chord lies within e_line of the curve S(c) (line_bound);
//  - the region of S between the uv curve c and the uv chord l is swept by the
//    segments [c(s), x(s)], x(s) the point of l nearest to c(s) (a homotopy from c
//    to a path along l with the same ends covers every point the closed curve
//    c + l winds around), each at most d_uv = max_s dist(c(s), l) long in (u,v);
//    so a point X of S there lies within e_uv = speed d_uv of S(c(s)), which is
//    within e_line of the 3D chord, and of S(x(s)), which is within F/8 of it
//    (chord_sag_bound): X is within e_uv + min(e_line, F/8) of the mesh boundary.
//    d_uv is bounded as line_bound bounds the 3D distance, on the uv control points
//    (not |c(s) - l(s)| at equal s, whose tangential part is no distance).
// So the piece is accepted when max(e_line, e_uv + min(e_line, F/8)) <= budget.
double piece_error(double e_line, double e_uv, double sag) {
    return std::max(e_line, e_uv + std::min(e_line, sag));
}

// line_bound of the uv curve: its homogeneous points (w u, w v, w) as (w u, w v, 0, w).
double uv_line_bound(const std::vector<Eigen::Vector3d>& P2) {
    std::vector<Eigen::Vector4d> h(P2.size());
    for (size_t i = 0; i < P2.size(); ++i) h[i] << P2[i].x(), P2[i].y(), 0.0, P2[i].z();
    return line_bound(h);
}

struct Subdivider {
    double budget;       // γ·tol
    double speed;        // sqrt((M^u)² + (M^v)²) over the piece's region
    SurfaceDerivativeBounds M;  // over the piece's region
    std::vector<double>* s_out;  // right ends of accepted pieces, in order

    double error(const std::vector<Eigen::Vector4d>& P3, const std::vector<Eigen::Vector3d>& P2) const {
        return piece_error(line_bound(P3), speed * uv_line_bound(P2), chord_sag_bound(P2, M));
    }

    // Equal pieces for a piece of error e: k from the 1/k^2 decay of the bound, then
    // corrected by the largest error of three trial pieces of 1/k (first, middle,
    // last), because the bound of a long piece overstates its curvature.
    int planned_pieces(const std::vector<Eigen::Vector4d>& P3, const std::vector<Eigen::Vector3d>& P2,
                       double e) const {
        const double first = std::ceil(std::sqrt(e / budget));
        if (!std::isfinite(first)) return 2;
        const int k = static_cast<int>(std::clamp(first, 2.0, double(kMaxPlannedPieces)));
        double e_small = 0.0;
        for (int i : {0, k / 2, k - 1})
            e_small = std::max(e_small, error(bezier_piece(P3, double(i) / k, double(i + 1) / k),
                                              bezier_piece(P2, double(i) / k, double(i + 1) / k)));
        const double second = std::ceil(k * std::sqrt(e_small / budget));
        if (!std::isfinite(second)) return k;
        return static_cast<int>(std::clamp(second, 2.0, double(kMaxPlannedPieces)));
    }

    void run(const std::vector<Eigen::Vector4d>& P3, const std::vector<Eigen::Vector3d>& P2,
             double sa, double sb, int depth) {
        const double e = error(P3, P2);
        if (e <= budget || depth >= kMaxSubdivisionDepth) {
            s_out->push_back(sb);
            return;
        }
        // k equal pieces (planned_pieces); a piece that still misses the budget is cut
        // again. Departure from [Balazs] Sec. 5.1's halving, whose power-of-two
        // counts overshoot by up to 2x.
        const int k = planned_pieces(P3, P2, e);
        std::vector<Eigen::Vector4d> rest3 = P3, L3, R3;
        std::vector<Eigen::Vector3d> rest2 = P2, L2, R2;
        for (int i = 0; i < k; ++i) {
            const double s0 = sa + (sb - sa) * i / k, s1 = i + 1 == k ? sb : sa + (sb - sa) * (i + 1) / k;
            if (i + 1 == k) {
                run(rest3, rest2, s0, s1, depth + 1);
                break;
            }
            const double t = 1.0 / (k - i);
            split_bezier(rest3, t, &L3, &R3);
            split_bezier(rest2, t, &L2, &R2);
            run(L3, L2, s0, s1, depth + 1);
            rest3.swap(R3);
            rest2.swap(R2);
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
                   const std::vector<double>& s_values, TrimPolyline* out) {
    for (double s : s_values) {
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
                                    double tolerance, TrimMethod method) {
    if (!std::isfinite(tolerance) || !(tolerance > 0.0))
        throw geom::InvalidInput("approximate_trim_curve: tolerance = " +
                                 geom::format_value(tolerance) + "; expected a finite value > 0");
    TrimPolyline out;
    const double ta = c.domain().first;
    append_points(S, c, ta, ta, {1.0}, &out);

    switch (method) {
    case TrimMethod::kBezier3d: {
        const double budget = kTrimGamma * tolerance;
        for (const LiftedPiece& piece : lift_trim_curve(S, c)) {
            if (!piece.exact) {
                const long n = yang_steps(S, c, piece.t0, piece.t1, budget);
                append_points(S, c, piece.t0, piece.t1, uniform_steps(n), &out);
                continue;
            }
            const std::vector<Eigen::Vector3d> P2 = homogeneous_piece(c, piece.t0, piece.t1);
            Eigen::AlignedBox2d box;
            for (const auto& h : P2) box.extend(project(h));
            const SurfaceDerivativeBounds Ms = surface_derivative_bounds(S, box);
            std::vector<double> s_values;
            Subdivider{budget, std::hypot(Ms.Mu, Ms.Mv), Ms, &s_values}.run(piece.P, P2, 0.0, 1.0, 0);
            append_points(S, c, piece.t0, piece.t1, s_values, &out);
        }
        const geom::NurbsCurve2d::Box box = c.control_box();
        const SurfaceDerivativeBounds Ms =
            surface_derivative_bounds(S, Eigen::AlignedBox2d(box.min(), box.max()));
        simplify_trim_polyline(&out, (1.0 - kTrimGamma) * tolerance, std::hypot(Ms.Mu, Ms.Mv));
        break;
    }
    case TrimMethod::kYang: {
        const std::vector<double> breaks = trim_curve_breaks(S, c);
        for (size_t i = 0; i + 1 < breaks.size(); ++i) {
            const long n = yang_steps(S, c, breaks[i], breaks[i + 1], tolerance);
            append_points(S, c, breaks[i], breaks[i + 1], uniform_steps(n), &out);
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
            append_points(S, c, t0, t1, uniform_steps(n), &out);
        }
        break;
    }
    }
    return out;
}

}  // namespace trimkit::tess
