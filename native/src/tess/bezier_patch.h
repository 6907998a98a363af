// BezierPatch: one rational tensor-product Bezier patch in homogeneous form, as
// the kd-tree subdivision [Balazs] Sec. 5.2 cuts it. Local parameters (s, t) in
// [0,1]^2 map linearly to the patch's (u,v) rectangle [u0,u1] x [v0,v1].
// `Pw`: (p+1)(q+1) homogeneous points (w*x, w*y, w*z, w), v fastest:
// point (i, j) is Pw[i * (q+1) + j], i along u.
#pragma once

#include <utility>
#include <vector>

#include <Eigen/Core>

#include "geom/bspline_basis.h"
#include "geom/nurbs_surface.h"

namespace trimkit::tess {

struct BezierPatch {
    int p = 0, q = 0;  // degrees in u and v
    std::vector<Eigen::Vector4d> Pw;
    double u0 = 0, u1 = 1, v0 = 0, v1 = 1;

    const Eigen::Vector4d& point(int i, int j) const { return Pw[i * (q + 1) + j]; }
    // Euclidean control point (i, j).
    Eigen::Vector3d euclidean(int i, int j) const {
        const Eigen::Vector4d& h = point(i, j);
        return h.head<3>() / h[3];
    }
    // S at local parameters (s, t) by de Casteljau on the homogeneous points: each
    // row i along t (column_at), then the rows' points along s (along_s).
    Eigen::Vector3d evaluate(double s, double t) const;
    // Row i's homogeneous point at t (de Casteljau over j).
    Eigen::Vector4d column_at(int i, double t) const;
    // The homogeneous points columns[0..p] combined at s and projected: with
    // columns[i] = column_at(i, t), exactly evaluate(s, t). For a curve of S at a
    // fixed t, the columns are computed once.
    Eigen::Vector3d along_s(const Eigen::Vector4d* columns, double s) const;
};

// A patch of `surface`'s bezier_patches() (Bezier knot vectors) in homogeneous form.
BezierPatch bezier_patch(const geom::NurbsSurface& bezier);

// The two halves of `patch` cut at local parameter s in (0,1) along u (de Casteljau).
std::pair<BezierPatch, BezierPatch> split_u(const BezierPatch& patch, double s);
// The same along v at local parameter t.
std::pair<BezierPatch, BezierPatch> split_v(const BezierPatch& patch, double t);

// `patch` restricted to [u0,u1] x [v0,v1], a sub-rectangle of its own.
BezierPatch restrict_patch(const BezierPatch& patch, double u0, double u1, double v0, double v1);

}  // namespace trimkit::tess
