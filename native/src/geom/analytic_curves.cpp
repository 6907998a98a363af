#include "geom/analytic_curves.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "geom/arc_parameter_map.h"
#include "geom/error.h"

namespace trimkit::geom {

namespace {

template <class Derived>
std::string str(const Eigen::MatrixBase<Derived>& v) {
    std::ostringstream s;
    s << "(" << v.transpose() << ")";
    return s.str();
}

void require_finite(bool ok, const char* owner, const std::string& what) {
    if (!ok) throw InvalidInput(std::string(owner) + ": " + what + " must be finite");
}

void require_domain(double t0, double t1, const char* owner) {
    require_finite(std::isfinite(t0) && std::isfinite(t1), owner, "parameter range");
    if (!(t0 < t1)) {
        std::ostringstream msg;
        msg << owner << ": parameter range [" << t0 << ", " << t1 << "]; expected t0 < t1";
        throw InvalidInput(msg.str());
    }
}

template <int Dim>
NurbsCurve<Dim> line_segment_impl(const Eigen::Matrix<double, Dim, 1>& P0,
                                  const Eigen::Matrix<double, Dim, 1>& P1, double t0,
                                  double t1) {
    require_finite(P0.allFinite() && P1.allFinite(), "line_segment", "end points");
    require_domain(t0, t1, "line_segment");
    return NurbsCurve<Dim>(1, {t0, t0, t1, t1}, {P0, P1});
}

// ---- 2D conic geometry for rational_quadratic_arc (frame: origin P0, chord on x) ----

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() * b.y() - a.y() * b.x();
}

// Q(x) = L0(x) L2(x) - κ y(x)², L0, L2: signed distances to the tangent lines,
// y: distance from the chord line (the x axis of the frame).
struct Conic {
    Eigen::Vector2d p0, t0, p2, t2;
    double kappa = 0;

    double L0(const Eigen::Vector2d& x) const { return cross2(t0, x - p0); }
    double L2(const Eigen::Vector2d& x) const { return cross2(t2, x - p2); }
    double Q(const Eigen::Vector2d& x) const { return L0(x) * L2(x) - kappa * x.y() * x.y(); }
    // Coefficients c0 + c1 s + c2 s² of Q(x + s d) (exact: Q is quadratic).
    Eigen::Vector3d along(const Eigen::Vector2d& x, const Eigen::Vector2d& d) const {
        const double a0 = L0(x), a1 = cross2(t0, d);
        const double b0 = L2(x), b1 = cross2(t2, d);
        const double y0 = x.y(), y1 = d.y();
        return {a0 * b0 - kappa * y0 * y0, a0 * b1 + a1 * b0 - 2 * kappa * y0 * y1,
                a1 * b1 - kappa * y1 * y1};
    }
    // Gradient ∇Q(x) = L2 ∇L0 + L0 ∇L2 - 2κ y e_y, with ∇L = (-t.y, t.x).
    Eigen::Vector2d gradient(const Eigen::Vector2d& x) const {
        const Eigen::Vector2d g0(-t0.y(), t0.x()), g2(-t2.y(), t2.x());
        return L2(x) * g0 + L0(x) * g2 - Eigen::Vector2d(0, 2 * kappa * x.y());
    }
};

// Real roots of c0 + c1 s + c2 s² (numerically stable form); empty if none.
std::vector<double> quadratic_roots(const Eigen::Vector3d& c) {
    const double c0 = c[0], c1 = c[1], c2 = c[2];
    const double scale = std::max({std::abs(c0), std::abs(c1), std::abs(c2)});
    if (scale == 0) return {};
    if (std::abs(c2) <= 1e-14 * scale) {
        if (c1 == 0) return {};
        return {-c0 / c1};
    }
    const double disc = c1 * c1 - 4 * c2 * c0;
    if (disc < 0) return {};
    const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
    std::vector<double> r{q / c2};
    if (q != 0) r.push_back(c0 / q);
    return r;
}

struct ConicSegment {
    Eigen::Vector2d A, P1, B;
    double w;
};

// One standard-form segment A -> B (tangents tA, tB), or two when it turns too far.
// [PT] Algorithm A7.3 in effect; the weight comes from the shoulder point, A7.2.
void conic_segments(const Conic& q, const Eigen::Vector2d& A, const Eigen::Vector2d& tA,
                    const Eigen::Vector2d& B, const Eigen::Vector2d& tB, int depth,
                    std::vector<ConicSegment>& out) {
    const double turn = std::abs(std::atan2(cross2(tA, tB), tA.dot(tB)));
    // P1 = A + a tA = B - b tB.
    const double det = cross2(tA, tB);
    const Eigen::Vector2d AB = B - A;
    const double scale = AB.norm();
    bool single = std::abs(det) > kAnalyticTolerance && turn <= kMaxSingleArcTurn;
    double a = 0, b = 0;
    if (single) {
        a = cross2(AB, tB) / det;
        b = cross2(tA, AB) / det;
        single = a > kAnalyticTolerance * scale && b > kAnalyticTolerance * scale;
    }
    if (single) {
        const Eigen::Vector2d P1 = A + a * tA;
        const Eigen::Vector2d M = 0.5 * (A + B);
        double s = -1;
        for (double r : quadratic_roots(q.along(M, P1 - M)))
            if (r > 0 && r < 1) s = r;
        if (s <= 0) {
            throw InvalidInput(
                "rational_quadratic_arc: the conic through the given point does not cross "
                "the triangle of the arc's end tangents; the tangents and point are "
                "inconsistent");
        }
        out.push_back({A, P1, B, s / (1 - s)});
        return;
    }
    if (depth >= 2) {
        throw InvalidInput(
            "rational_quadratic_arc: no conic arc leaves the start point along T0 and "
            "reaches the end point along T2 (arc through infinity or inconsistent tangents)");
    }
    // Split at the arc's extreme point from the chord: tangent parallel to the chord,
    // on the side tA points to; its tangent direction is +chord (re-derived).
    const Eigen::Vector2d e = AB / scale;
    const double side = cross2(e, tA) >= 0 ? 1.0 : -1.0;
    // ∇Q(x)·e = 0 is the line g·x + h = 0 with g = H e (H the Hessian of Q).
    const Eigen::Vector2d g = q.gradient(e) - q.gradient(Eigen::Vector2d::Zero());
    const double h = q.gradient(Eigen::Vector2d::Zero()).dot(e);
    if (g.norm() <= kAnalyticTolerance) {
        throw InvalidInput("rational_quadratic_arc: degenerate conic (no point with tangent "
                           "parallel to the chord)");
    }
    const Eigen::Vector2d x0 = -h * g / g.squaredNorm();
    const Eigen::Vector2d dir(-g.y(), g.x());
    double best = 0;
    Eigen::Vector2d S;
    bool found = false;
    for (double r : quadratic_roots(q.along(x0, dir))) {
        const Eigen::Vector2d x = x0 + r * dir;
        const double height = side * cross2(e, x - A);
        if (height > best) {
            best = height;
            S = x;
            found = true;
        }
    }
    if (!found || best <= kAnalyticTolerance * scale) {
        throw InvalidInput("rational_quadratic_arc: the conic has no arc from the start "
                           "point along T0 to the end point");
    }
    conic_segments(q, A, tA, S, e, depth + 1, out);
    conic_segments(q, S, e, B, tB, depth + 1, out);
}

}  // namespace

NurbsCurve3d line_segment(const Eigen::Vector3d& P0, const Eigen::Vector3d& P1, double t0,
                          double t1) {
    return line_segment_impl<3>(P0, P1, t0, t1);
}

NurbsCurve2d line_segment(const Eigen::Vector2d& P0, const Eigen::Vector2d& P1, double t0,
                          double t1) {
    return line_segment_impl<2>(P0, P1, t0, t1);
}

NurbsCurve3d ellipse_arc(const Eigen::Vector3d& center, const Eigen::Vector3d& x_axis,
                         const Eigen::Vector3d& y_axis, double a, double b, double theta0,
                         double theta1) {
    const char* owner = "ellipse_arc";
    require_finite(center.allFinite() && x_axis.allFinite() && y_axis.allFinite() &&
                       std::isfinite(a) && std::isfinite(b),
                   owner, "center, axes and semi-axes");
    if (!(a > 0) || !(b > 0)) {
        std::ostringstream msg;
        msg << owner << ": semi-axes a = " << a << ", b = " << b << "; expected both > 0";
        throw InvalidInput(msg.str());
    }
    const double nx = x_axis.norm(), ny = y_axis.norm();
    if (nx == 0 || ny == 0) {
        throw InvalidInput(std::string(owner) + ": x_axis " + str(x_axis) + " or y_axis " +
                           str(y_axis) + " has zero length");
    }
    const Eigen::Vector3d X = x_axis / nx;
    const Eigen::Vector3d Yp = y_axis / ny - X.dot(y_axis / ny) * X;
    if (Yp.norm() <= kAnalyticTolerance) {
        throw InvalidInput(std::string(owner) + ": x_axis " + str(x_axis) + " and y_axis " +
                           str(y_axis) + " are parallel; expected two directions of a plane");
    }
    const Eigen::Vector3d Y = Yp.normalized();
    const ArcParameterMap map(theta0, theta1);
    std::vector<Eigen::Vector3d> P;
    for (const Eigen::Vector2d& c : map.unit_circle_points())
        P.push_back(center + a * c.x() * X + b * c.y() * Y);
    return NurbsCurve3d(2, map.knot_vector(), std::move(P), map.weights());
}

NurbsCurve3d circular_arc(const Eigen::Vector3d& center, const Eigen::Vector3d& x_axis,
                          const Eigen::Vector3d& y_axis, double radius, double theta0,
                          double theta1) {
    if (!(radius > 0) || !std::isfinite(radius)) {
        std::ostringstream msg;
        msg << "circular_arc: radius = " << radius << "; expected a finite value > 0";
        throw InvalidInput(msg.str());
    }
    return ellipse_arc(center, x_axis, y_axis, radius, radius, theta0, theta1);
}

NurbsCurve3d rational_quadratic_arc(const Eigen::Vector3d& P0, const Eigen::Vector3d& T0,
                                    const Eigen::Vector3d& P2, const Eigen::Vector3d& T2,
                                    const Eigen::Vector3d& P_on) {
    const char* owner = "rational_quadratic_arc";
    require_finite(P0.allFinite() && T0.allFinite() && P2.allFinite() && T2.allFinite() &&
                       P_on.allFinite(),
                   owner, "points and tangents");
    const double L = (P2 - P0).norm();
    if (L == 0) throw InvalidInput(std::string(owner) + ": start and end point coincide at " + str(P0));
    if (T0.norm() == 0 || T2.norm() == 0) {
        throw InvalidInput(std::string(owner) + ": tangent T0 " + str(T0) + " or T2 " +
                           str(T2) + " has zero length");
    }
    const Eigen::Vector3d e1 = (P2 - P0) / L;
    const Eigen::Vector3d t0 = T0.normalized(), t2 = T2.normalized();
    // Plane normal from whichever datum is farthest from the chord line.
    Eigen::Vector3d n = e1.cross(t0);
    for (const Eigen::Vector3d& c : {e1.cross(t2), e1.cross((P_on - P0) / L)})
        if (c.norm() > n.norm()) n = c;
    if (n.norm() <= kAnalyticTolerance) {
        throw InvalidInput(std::string(owner) + ": tangents and the point " + str(P_on) +
                           " all lie on the chord line; a conic needs a plane");
    }
    n.normalize();
    Eigen::Vector3d e2 = n.cross(e1);
    if (std::abs(t0.dot(n)) > kAnalyticTolerance || std::abs(t2.dot(n)) > kAnalyticTolerance ||
        std::abs((P_on - P0).dot(n)) > kAnalyticTolerance * L) {
        throw InvalidInput(std::string(owner) + ": end points, tangents and " + str(P_on) +
                           " are not coplanar");
    }
    auto to2 = [&](const Eigen::Vector3d& x) {
        return Eigen::Vector2d((x - P0).dot(e1), (x - P0).dot(e2));
    };
    auto dir2 = [&](const Eigen::Vector3d& d) { return Eigen::Vector2d(d.dot(e1), d.dot(e2)).normalized(); };
    Conic q;
    q.p0 = Eigen::Vector2d::Zero();
    q.p2 = to2(P2);
    q.t0 = dir2(t0);
    q.t2 = dir2(t2);
    const Eigen::Vector2d on = to2(P_on);
    if (std::abs(on.y()) <= kAnalyticTolerance * L) {
        throw InvalidInput(std::string(owner) + ": the point " + str(P_on) +
                           " lies on the chord line; expected a point off the chord");
    }
    if (std::abs(q.L0(on)) <= kAnalyticTolerance * L || std::abs(q.L2(on)) <= kAnalyticTolerance * L) {
        throw InvalidInput(std::string(owner) + ": the point " + str(P_on) +
                           " lies on an end tangent line; the conic would be a line pair");
    }
    q.kappa = q.L0(on) * q.L2(on) / (on.y() * on.y());

    std::vector<ConicSegment> segs;
    conic_segments(q, q.p0, q.t0, q.p2, q.t2, 0, segs);

    auto to3 = [&](const Eigen::Vector2d& x) -> Eigen::Vector3d {
        return P0 + x.x() * e1 + x.y() * e2;
    };
    const int k = static_cast<int>(segs.size());
    std::vector<double> U(3, 0.0);
    std::vector<Eigen::Vector3d> P{P0};
    std::vector<double> w{1.0};
    for (int i = 0; i < k; ++i) {
        P.push_back(to3(segs[i].P1));
        w.push_back(segs[i].w);
        P.push_back(i + 1 == k ? P2 : to3(segs[i].B));
        w.push_back(1.0);
        if (i + 1 < k) U.insert(U.end(), 2, double(i + 1) / k);
    }
    U.insert(U.end(), 3, 1.0);
    return NurbsCurve3d(2, std::move(U), std::move(P), std::move(w));
}

NurbsCurve2d to_2d(const NurbsCurve3d& c) {
    std::vector<Eigen::Vector2d> P;
    P.reserve(c.points().size());
    for (const auto& p : c.points()) P.emplace_back(p.x(), p.y());
    return NurbsCurve2d(c.degree(), c.knots(), std::move(P),
                        c.is_rational() ? c.weights() : std::vector<double>{});
}

NurbsCurve3d to_3d(const NurbsCurve2d& c, double z) {
    std::vector<Eigen::Vector3d> P;
    P.reserve(c.points().size());
    for (const auto& p : c.points()) P.emplace_back(p.x(), p.y(), z);
    return NurbsCurve3d(c.degree(), c.knots(), std::move(P),
                        c.is_rational() ? c.weights() : std::vector<double>{});
}

}  // namespace trimkit::geom
