// ArcParameterMap: the exact map between an angle θ and the NURBS parameter t of
// a circular (or elliptic) arc built from k equal rational quadratic segments.
// Conventions: the arc from θ0 to θ1 has k = ceil(|θ1 - θ0| / (π/2)) segments
// with boundary angles a_i = θ0 + i (θ1 - θ0)/k; the NURBS knots sit at σ·a_i,
// σ = sign(θ1 - θ0), so t = σ·θ at every knot and the domain is [σθ0, σθ1]
// (for a counter-clockwise arc t equals θ at the knots; a clockwise arc uses
// t = -θ so that the knots increase while the curve still starts at θ0).
#pragma once

#include <vector>

#include <Eigen/Core>

namespace trimkit::geom {

// Sweeps within kAngleSlack (radians) of a multiple of π/2 do not get an extra
// segment, and sweeps up to 2π + kAngleSlack are accepted as full circles.
// 1e-12 rad is far above the rounding of angles read from files (~1e-16·2π)
// and far below any real CAD angle.
constexpr double kAngleSlack = 1e-12;

class ArcParameterMap {
public:
    // Throws InvalidInput if an angle is non-finite, θ0 == θ1, or
    // |θ1 - θ0| > 2π (+ kAngleSlack).
    ArcParameterMap(double theta0, double theta1);

    double theta0() const { return theta0_; }
    double theta1() const { return theta1_; }
    int segments() const { return k_; }
    // +1 for θ1 > θ0 (counter-clockwise), -1 otherwise.
    int direction() const { return sigma_; }
    // Distinct knot values t_0 < .. < t_k (t_i = σ·a_i); t_0 and t_k are σθ0, σθ1 exactly.
    const std::vector<double>& knots() const { return t_; }
    // Boundary angles a_0 .. a_k (a_0 = θ0, a_k = θ1 exactly).
    const std::vector<double>& angles() const { return a_; }
    // Half of one segment's signed sweep: α = (θ1 - θ0) / (2k); the middle
    // control point of every segment has weight cos α.
    double half_angle() const { return half_; }

    // NURBS parameter of angle θ; θ outside [θ0, θ1] is clamped to it.
    // Inside segment i, with ψ = θ - a_i - α and local s ∈ [0, 1]:
    //   tan(ψ/2) = tan(α/2) (2s - 1),  t = σ (a_i + 2α s).
    // Re-derived from [PT] Sec. 7.5 (circle segment with w1 = cos α); the
    // rational quadratic circle is a Möbius map of tan of the half angle.
    double to_nurbs(double theta) const;
    // Angle θ of NURBS parameter t; t outside the domain is clamped to it.
    // Exact inverse of to_nurbs.
    double to_angle(double t) const;
    // dt/dθ at θ (clamped); equals σ|α| / sin|α| at every knot, so the map is
    // C1 but its second derivative jumps at the knots.
    double nurbs_derivative(double theta) const;

    // The arc of the unit circle (cos θ, sin θ) from θ0 to θ1 as a degree-2
    // rational B-spline: knot_vector() (ends tripled, knots() doubled inside),
    // 2k+1 unit_circle_points() and weights() (1 at the knots, cos α between).
    // [PT] Sec. 7.5, Algorithm A7.1 with equal segments. Affine images of these
    // points give circles, ellipses and the rows of surfaces of revolution.
    std::vector<double> knot_vector() const;
    std::vector<Eigen::Vector2d> unit_circle_points() const;
    std::vector<double> weights() const;

private:
    // Segment index of the forward angle λ = σθ (clamped to [0, k-1]).
    int segment_of(double lambda) const;

    double theta0_ = 0, theta1_ = 0;
    int sigma_ = 1;
    int k_ = 1;
    double half_ = 0;        // α (signed)
    double tan_quarter_ = 0; // tan(|α|/2)
    std::vector<double> a_, t_;
};

}  // namespace trimkit::geom
