// NurbsCurve<Dim>: a (possibly rational) B-spline curve in 2D (trim curves in a
// face's (u,v) domain) or 3D (model-space edges). Control points are stored
// Euclidean with a separate weight per point (all 1 when not rational). The
// parameter domain is [U[p], U[n+1]], n = #points - 1.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <utility>
#include <vector>

namespace trimkit::geom {

template <int Dim>
class NurbsCurve {
public:
    using Point = Eigen::Matrix<double, Dim, 1>;
    using Box = Eigen::AlignedBox<double, Dim>;

    NurbsCurve() = default;
    // Throws InvalidInput if degree < 1 or > kMaxDegree, the knot vector is invalid
    // for the point count, any value is non-finite, or a weight is <= 0.
    // Empty `weights` means non-rational.
    NurbsCurve(int degree, std::vector<double> knots, std::vector<Point> points,
               std::vector<double> weights = {});

    int degree() const { return p_; }
    const std::vector<double>& knots() const { return U_; }
    const std::vector<Point>& points() const { return P_; }
    const std::vector<double>& weights() const { return w_; }  // size == points().size()
    bool is_rational() const { return rational_; }
    std::pair<double, double> domain() const;

    // t outside the domain is clamped to it (no extrapolation).
    Point evaluate(double t) const;
    // C(t) and its derivatives up to `order` (<= 2 guaranteed, higher allowed);
    // result[k] is the k-th derivative. Rational: [PT] Algorithm A4.2.
    std::vector<Point> derivatives(double t, int order) const;

    // Knot insertion of t, `times` times (total multiplicity capped at p).
    // [PT] Algorithm A5.1, applied to homogeneous points. The shape is unchanged.
    NurbsCurve insert_knot(double t, int times = 1) const;
    // The curve restricted to [a, b] ⊂ domain, by knot insertion.
    NurbsCurve sub_curve(double a, double b) const;
    // One Bézier curve per non-empty knot span, in order. [PT] Algorithm A5.6 in effect.
    std::vector<NurbsCurve> bezier_segments() const;
    // Same geometry, opposite direction; domain [a,b] maps to [a,b].
    NurbsCurve reversed() const;
    // Same geometry on the domain [a, b] (affine reparameterisation of the knots).
    NurbsCurve reparameterized(double a, double b) const;

    // Box of the control points (contains the curve by the convex hull property).
    Box control_box() const;

    // The curve under an affine transform (exact for NURBS); Dim 2 or 3.
    NurbsCurve transformed(const Eigen::Transform<double, Dim, Eigen::Affine>& T) const;
    // The curve moved by `shift` (every control point; exact).
    NurbsCurve translated(const Point& shift) const;

private:
    // Pw = (w P, w) per control point, and the curve made from such points.
    std::vector<Eigen::Matrix<double, Dim + 1, 1>> homogeneous_points() const;
    static NurbsCurve from_homogeneous(int p, std::vector<double> knots,
                                       const std::vector<Eigen::Matrix<double, Dim + 1, 1>>& H,
                                       bool rational);

    int p_ = 0;
    std::vector<double> U_;
    std::vector<Point> P_;
    std::vector<double> w_;
    bool rational_ = false;
};

using NurbsCurve2d = NurbsCurve<2>;
using NurbsCurve3d = NurbsCurve<3>;

extern template class NurbsCurve<2>;
extern template class NurbsCurve<3>;

}  // namespace trimkit::geom
