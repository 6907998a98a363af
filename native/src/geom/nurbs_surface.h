// NurbsSurface: a (possibly rational) tensor-product B-spline surface in 3D.
// Control points form a grid of nu x nv points stored row-major with v fastest:
// point (i, j) is points()[i * nv + j], i along u, j along v. Weights are stored
// separately (all 1 when not rational). Domain [U[pu], U[nu]] x [V[pv], V[nv]].
#pragma once

#include <Eigen/Geometry>
#include <utility>
#include <vector>

namespace trimkit::geom {

// S and its partial derivatives at one parameter point.
struct SurfaceDerivatives {
    Eigen::Vector3d S, Su, Sv, Suu, Suv, Svv;
};

class NurbsSurface {
public:
    NurbsSurface() = default;
    // Throws InvalidInput if a degree is < 1 or > kMaxDegree, a knot vector is
    // invalid, points.size() != nu * nv, a value is non-finite or a weight <= 0.
    NurbsSurface(int degree_u, int degree_v, std::vector<double> knots_u,
                 std::vector<double> knots_v, int nu, int nv,
                 std::vector<Eigen::Vector3d> points, std::vector<double> weights = {});

    int degree_u() const { return pu_; }
    int degree_v() const { return pv_; }
    const std::vector<double>& knots_u() const { return U_; }
    const std::vector<double>& knots_v() const { return V_; }
    int count_u() const { return nu_; }
    int count_v() const { return nv_; }
    const std::vector<Eigen::Vector3d>& points() const { return P_; }
    const std::vector<double>& weights() const { return w_; }
    const Eigen::Vector3d& point(int i, int j) const { return P_[i * nv_ + j]; }
    double weight(int i, int j) const { return w_[i * nv_ + j]; }
    bool is_rational() const { return rational_; }
    // True when S(u, v) = a + u b + v c: degree (1, 1), one span, equal weights and a
    // parallelogram of control points (to 1e-12 of their extent). Such an S maps a
    // segment in (u,v) onto the segment between its ends' images.
    bool is_affine() const;
    std::pair<double, double> domain_u() const;
    std::pair<double, double> domain_v() const;

    // (u, v) outside the domain is clamped to it (no extrapolation).
    Eigen::Vector3d evaluate(double u, double v) const;
    // S, Su, Sv, Suu, Suv, Svv. Rational: [PT] Algorithm A4.4.
    // Throws NumericalFailure if the rational denominator vanishes.
    SurfaceDerivatives derivatives(double u, double v) const;
    // Unit normal Su x Sv (not flipped for face orientation). At a degenerate
    // point (pole of a sphere, apex of a cone) falls back to nearby second-order
    // terms; throws NumericalFailure only if no direction can be found.
    Eigen::Vector3d normal(double u, double v) const;

    // [PT] Algorithm A5.3 on homogeneous points; the shape is unchanged.
    NurbsSurface insert_knot_u(double u, int times = 1) const;
    NurbsSurface insert_knot_v(double v, int times = 1) const;
    // Bézier patches, row-major over (u spans, v spans), v fastest; each patch is a
    // NurbsSurface with Bézier knot vectors on its own sub-domain.
    std::vector<NurbsSurface> bezier_patches() const;
    // The surface restricted to [u0,u1] x [v0,v1] by knot insertion.
    NurbsSurface sub_surface(double u0, double u1, double v0, double v1) const;
    // Same geometry with u and v exchanged.
    NurbsSurface swapped_uv() const;

    Eigen::AlignedBox3d control_box() const;
    NurbsSurface transformed(const Eigen::Affine3d& T) const;

private:
    // Pw = (w P, w) of column j (points (0..nu-1, j)), and the surface made from such a grid.
    std::vector<Eigen::Vector4d> homogeneous_column(int j) const;
    static NurbsSurface from_homogeneous(int pu, int pv, std::vector<double> U, std::vector<double> V,
                                         int nu, int nv, const std::vector<Eigen::Vector4d>& grid,
                                         bool rational);

    int pu_ = 0, pv_ = 0;
    std::vector<double> U_, V_;
    int nu_ = 0, nv_ = 0;
    std::vector<Eigen::Vector3d> P_;
    std::vector<double> w_;
    bool rational_ = false;
};

}  // namespace trimkit::geom
