// BezierTriangle: a triangular Bezier patch of degree n (1 <= n <= 20) in 3D,
// b(u,v,w) = sum_{i+j+k=n} b_ijk * n!/(i! j! k!) * u^i v^j w^k with u+v+w = 1
// ([Garcia] Sec. 2). Control points are stored with i from n down to 0 and,
// within, j from n-i down to 0 (cubic: b300 b210 b201 b120 b111 b102 b030 b021
// b012 b003), so corner u = 1 is points()[0] and corner w = 1 is points().back().
// Parameters are barycentric triples (u, v, w); orientation: the normal is
// db/du x db/dv with w = 1 - u - v (corners u, v, w counter-clockwise seen from it).
#pragma once

#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace trimkit::geom {

constexpr int kMaxBezierTriangleDegree = 20;

class BezierTriangle {
public:
    BezierTriangle() = default;
    // Throws InvalidInput if degree is outside [1, 20], points.size() is not
    // (n+1)(n+2)/2, or a coordinate is non-finite.
    BezierTriangle(int degree, std::vector<Eigen::Vector3d> points);

    // (n+1)(n+2)/2.
    static int point_count(int degree) { return (degree + 1) * (degree + 2) / 2; }
    // Position of b_ijk (k = n - i - j) in the storage order above.
    static int index(int degree, int i, int j) {
        const int a = degree - i;
        return a * (a + 1) / 2 + (a - j);
    }

    int degree() const { return n_; }
    const std::vector<Eigen::Vector3d>& points() const { return b_; }
    const Eigen::Vector3d& point(int i, int j) const { return b_[index(n_, i, j)]; }
    // Corner c (0: u = 1, 1: v = 1, 2: w = 1); the patch interpolates it.
    const Eigen::Vector3d& corner(int c) const;

    // b(u, v, w) by de Casteljau's algorithm ([Garcia] Sec. 2, [Sei89]); the
    // triple need not sum to 1 exactly (it is used as given: blossom b(t,...,t)).
    Eigen::Vector3d evaluate(const Eigen::Vector3d& uvw) const;
    Eigen::Vector3d evaluate(double u, double v, double w) const { return evaluate(Eigen::Vector3d(u, v, w)); }

    // Directional derivative D_d b at uvw along the barycentric direction d
    // (components summing to 0): n * sum_{|l|=n-1} (d . (b_{l+e1}, b_{l+e2}, b_{l+e3})) B^{n-1}_l.
    Eigen::Vector3d derivative(const Eigen::Vector3d& uvw, const Eigen::Vector3d& d) const;
    // db/du and db/dv with w = 1 - u - v.
    Eigen::Vector3d derivative_u(const Eigen::Vector3d& uvw) const { return derivative(uvw, {1, 0, -1}); }
    Eigen::Vector3d derivative_v(const Eigen::Vector3d& uvw) const { return derivative(uvw, {0, 1, -1}); }
    // Unit normal (db/du x db/dv normalised). Where that vanishes (a degenerate
    // corner or edge) the normal is taken a little way towards the domain centre;
    // throws NumericalFailure if the patch is degenerate there too.
    Eigen::Vector3d normal(const Eigen::Vector3d& uvw) const;

    // Blossom b(t_1, ..., t_n) of the n barycentric arguments (polar form).
    Eigen::Vector3d blossom(const std::vector<Eigen::Vector3d>& args) const;

    // The patch restricted to the sub-triangle with barycentric corners r, s, t
    // (any points, inside the domain or not): control points c_ijk = blossom
    // b(r^i, s^j, t^k) ([Sei89], repeated de Casteljau). sub(u,v,w) = b(u r + v s + w t).
    BezierTriangle subpatch(const Eigen::Vector3d& r, const Eigen::Vector3d& s, const Eigen::Vector3d& t) const;

    // Box of the control points (contains the patch: convex hull property).
    Eigen::AlignedBox3d bounding_box() const;

private:
    int n_ = 0;
    std::vector<Eigen::Vector3d> b_;
};

}  // namespace trimkit::geom
