// NurbsCurve<Dim>: validation, evaluation ([PT] Ch. 3-4) and knot insertion
// based operations ([PT] Ch. 5). Rational operations work on homogeneous points
// Pw = (w P, w), the [PT] convention.
#include "geom/nurbs_curve.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "geom/bspline_basis.h"
#include "geom/error.h"
#include "geom/rational_weights.h"
#include "geom/knot_insertion.h"
#include "geom/knot_vector.h"

namespace trimkit::geom {

namespace {

template <int Dim>
std::string point_text(const Eigen::Matrix<double, Dim, 1>& P) {
    std::string text = "(";
    for (int d = 0; d < Dim; ++d) text += (d ? ", " : "") + format_value(P[d]);
    return text + ")";
}


}  // namespace

template <int Dim>
NurbsCurve<Dim>::NurbsCurve(int degree, std::vector<double> knots, std::vector<Point> points,
                            std::vector<double> weights) {
    const std::string owner = "NurbsCurve";
    // Degree first: nothing below allocates in proportion to it.
    if (degree < 1 || degree > kMaxDegree)
        throw InvalidInput(owner + ": degree " + std::to_string(degree) + "; expected 1.." +
                           std::to_string(kMaxDegree) + " (kMaxDegree)");
    if (!weights.empty() && weights.size() != points.size())
        throw InvalidInput(owner + ": " + std::to_string(weights.size()) + " weights for " +
                           std::to_string(points.size()) +
                           " control points; expected one weight per point, or none");
    validate_knot_vector(knots, degree, static_cast<int>(points.size()), owner);
    for (size_t i = 0; i < points.size(); ++i)
        if (!points[i].allFinite())
            throw InvalidInput(owner + ": point[" + std::to_string(i) + "] = " +
                               point_text<Dim>(points[i]) + "; control points must be finite");
    const bool rational = validate_rational_weights(weights, owner);
    if (weights.empty()) weights.assign(points.size(), 1.0);
    p_ = degree;
    U_ = std::move(knots);
    P_ = std::move(points);
    w_ = std::move(weights);
    rational_ = rational;
}

template <int Dim>
std::pair<double, double> NurbsCurve<Dim>::domain() const {
    return {U_[p_], U_[U_.size() - p_ - 1]};
}

// [PT] Algorithm A4.1 (A3.1 when not rational). t is clamped to the domain.
template <int Dim>
typename NurbsCurve<Dim>::Point NurbsCurve<Dim>::evaluate(double t) const {
    const auto [a, b] = domain();
    t = std::min(std::max(t, a), b);
    const int span = knot_span(U_, p_, t);
    double N[kMaxDegree + 1];
    basis_functions(U_, p_, span, t, N);
    const int first = span - p_;
    Point C = Point::Zero();
    if (!rational_) {
        for (int j = 0; j <= p_; ++j) C += N[j] * P_[first + j];
        return C;
    }
    double W = 0.0;
    for (int j = 0; j <= p_; ++j) {
        const double c = N[j] * w_[first + j];
        C += c * P_[first + j];
        W += c;
    }
    return C / W;  // W >= min weight > 0: basis functions are a partition of unity
}

// [PT] Algorithm A3.2 on the homogeneous points, then A4.2 for the rational case:
// C^(k) = (A^(k) - sum_{i=1..k} binom(k,i) w^(i) C^(k-i)) / w.
template <int Dim>
std::vector<typename NurbsCurve<Dim>::Point> NurbsCurve<Dim>::derivatives(double t,
                                                                          int order) const {
    if (order < 0)
        throw InvalidInput("NurbsCurve::derivatives: order " + std::to_string(order) +
                           "; expected >= 0");
    const auto [a, b] = domain();
    t = std::min(std::max(t, a), b);
    const int span = knot_span(U_, p_, t);
    const int du = std::min(order, p_);
    double ders[(kMaxDegree + 1) * (kMaxDegree + 1)];
    basis_function_derivatives(U_, p_, span, t, du, ders);
    const int first = span - p_, stride = p_ + 1;

    std::vector<Point> CK(order + 1, Point::Zero());
    if (!rational_) {
        for (int k = 0; k <= du; ++k)
            for (int j = 0; j <= p_; ++j) CK[k] += ders[k * stride + j] * P_[first + j];
        return CK;
    }
    // A^(k) is accumulated into CK[k] and replaced by C^(k) in order of k.
    std::vector<double> W(order + 1, 0.0);
    for (int k = 0; k <= du; ++k)
        for (int j = 0; j <= p_; ++j) {
            const double c = ders[k * stride + j] * w_[first + j];
            CK[k] += c * P_[first + j];
            W[k] += c;
        }
    if (!(W[0] > 0.0))
        throw NumericalFailure("NurbsCurve: rational denominator " + format_value(W[0]) +
                               " at t = " + format_value(t));
    std::vector<double> binom(order + 1, 0.0);  // row k of Pascal's triangle
    for (int k = 0; k <= order; ++k) {
        binom[k] = 1.0;
        for (int i = k - 1; i >= 1; --i) binom[i] += binom[i - 1];
        Point v = CK[k];
        for (int i = 1; i <= std::min(k, du); ++i) v -= binom[i] * W[i] * CK[k - i];
        CK[k] = v / W[0];
    }
    return CK;
}

// [PT] Algorithm A5.1 on homogeneous points Pw = (w P, w) (geom/knot_insertion.h).
template <int Dim>
NurbsCurve<Dim> NurbsCurve<Dim>::insert_knot(double t, int times) const {
    const KnotInsertion plan = plan_knot_insertion(U_, p_, t, times, "NurbsCurve::insert_knot");
    if (plan.r == 0) return *this;
    return from_homogeneous(p_, plan.knots, geom::insert_knot(plan, homogeneous_points()), rational_);
}

template <int Dim>
std::vector<HomogeneousPoint<Dim>> NurbsCurve<Dim>::homogeneous_points() const {
    std::vector<HomogeneousPoint<Dim>> H(P_.size());
    for (size_t i = 0; i < P_.size(); ++i) H[i] = homogeneous<Dim>(P_[i], w_[i]);
    return H;
}

template <int Dim>
NurbsCurve<Dim> NurbsCurve<Dim>::from_homogeneous(int p, std::vector<double> knots,
                                                  const std::vector<HomogeneousPoint<Dim>>& H,
                                                  bool rational) {
    NurbsCurve result;
    result.p_ = p;
    result.rational_ = rational;
    result.U_ = std::move(knots);
    result.P_.resize(H.size());
    result.w_.resize(H.size());
    for (size_t i = 0; i < H.size(); ++i) {
        result.w_[i] = rational ? H[i][Dim] : 1.0;
        result.P_[i] = euclidean<Dim>(H[i], rational);
    }
    return result;
}

namespace {

// The part of `c` over [a, b], where a and b are knots of multiplicity >= p
// (so the part is clamped at both ends): points P[la-p .. fb-1] with la the last
// knot index at a and fb the first at b.
template <int Dim>
NurbsCurve<Dim> extract(const NurbsCurve<Dim>& c, double a, double b) {
    const auto& U = c.knots();
    const int p = c.degree();
    const int la = static_cast<int>(std::upper_bound(U.begin(), U.end(), a) - U.begin()) - 1;
    const int fb = static_cast<int>(std::lower_bound(U.begin(), U.end(), b) - U.begin());
    std::vector<double> knots(p + 1, a);
    knots.insert(knots.end(), U.begin() + la + 1, U.begin() + fb);
    knots.insert(knots.end(), p + 1, b);
    std::vector<typename NurbsCurve<Dim>::Point> points(c.points().begin() + (la - p),
                                                        c.points().begin() + fb);
    std::vector<double> weights;
    if (c.is_rational())
        weights.assign(c.weights().begin() + (la - p), c.weights().begin() + fb);
    return NurbsCurve<Dim>(p, std::move(knots), std::move(points), std::move(weights));
}

}  // namespace

template <int Dim>
NurbsCurve<Dim> NurbsCurve<Dim>::sub_curve(double a, double b) const {
    const auto [lo, hi] = domain();
    const double tol = kKnotTolerance * (hi - lo);
    if (!(a < b) || a < lo - tol || b > hi + tol)
        throw InvalidInput("NurbsCurve::sub_curve: [" + format_value(a) + ", " +
                           format_value(b) + "]; expected a < b inside the domain [" +
                           format_value(lo) + ", " + format_value(hi) + "]");
    a = snap_to_knot(U_, std::max(a, lo), tol);
    b = snap_to_knot(U_, std::min(b, hi), tol);
    if (!(a < b))
        throw InvalidInput("NurbsCurve::sub_curve: [" + format_value(a) + ", " +
                           format_value(b) + "] is shorter than the knot tolerance");
    return extract(insert_knot(a, p_).insert_knot(b, p_), a, b);
}

// [PT] Algorithm A5.6 (geom/knot_insertion.h): one clamped piece per span.
template <int Dim>
std::vector<NurbsCurve<Dim>> NurbsCurve<Dim>::bezier_segments() const {
    const DomainClamp clamp = plan_domain_clamp(U_, p_, "NurbsCurve::bezier_segments");
    const std::vector<HomogeneousPoint<Dim>> pieces = bezier_pieces(clamp, p_, homogeneous_points());
    const std::vector<double>& breaks = clamp.breaks;
    const size_t width = static_cast<size_t>(p_) + 1;
    std::vector<NurbsCurve> segments;
    segments.reserve(breaks.size() - 1);
    for (size_t q = 0; q + 1 < breaks.size(); ++q) {
        std::vector<HomogeneousPoint<Dim>> H(pieces.begin() + q * width, pieces.begin() + (q + 1) * width);
        segments.push_back(from_homogeneous(p_, bezier_knots(p_, breaks[q], breaks[q + 1]), H, rational_));
    }
    return segments;
}

template <int Dim>
NurbsCurve<Dim> NurbsCurve<Dim>::reversed() const {
    const auto [a, b] = domain();
    NurbsCurve result = *this;
    const size_t m = U_.size() - 1;
    for (size_t i = 0; i <= m; ++i) {
        const double x = U_[m - i];
        // Knots inside the domain stay inside it exactly, whatever the rounding.
        result.U_[i] = (x >= a && x <= b) ? std::min(std::max(a + b - x, a), b) : a + b - x;
        if (x == a) result.U_[i] = b;
        if (x == b) result.U_[i] = a;
    }
    std::reverse(result.P_.begin(), result.P_.end());
    std::reverse(result.w_.begin(), result.w_.end());
    return result;
}

template <int Dim>
NurbsCurve<Dim> NurbsCurve<Dim>::reparameterized(double a, double b) const {
    if (!(a < b) || !std::isfinite(a) || !std::isfinite(b))
        throw InvalidInput("NurbsCurve::reparameterized: domain [" + format_value(a) + ", " +
                           format_value(b) + "]; expected finite a < b");
    const auto [u0, u1] = domain();
    const double scale = (b - a) / (u1 - u0);
    NurbsCurve result = *this;
    for (double& x : result.U_) {
        if (x == u0) x = a;
        else if (x == u1) x = b;
        else if (x > u0 && x < u1) x = std::min(std::max(a + (x - u0) * scale, a), b);
        else x = a + (x - u0) * scale;
    }
    return result;
}

template <int Dim>
typename NurbsCurve<Dim>::Box NurbsCurve<Dim>::control_box() const {
    Box box;
    for (const Point& P : P_) box.extend(P);
    return box;
}

template <int Dim>
NurbsCurve<Dim> NurbsCurve<Dim>::transformed(
    const Eigen::Transform<double, Dim, Eigen::Affine>& T) const {
    NurbsCurve result = *this;
    for (Point& P : result.P_) P = T * P;
    return result;
}

template <int Dim>
NurbsCurve<Dim> NurbsCurve<Dim>::translated(const Point& shift) const {
    NurbsCurve result = *this;
    for (Point& P : result.P_) P += shift;
    return result;
}

template class NurbsCurve<2>;
template class NurbsCurve<3>;

}  // namespace trimkit::geom
