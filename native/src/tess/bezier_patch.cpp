#include "tess/bezier_patch.h"

#include <algorithm>
#include <cassert>
#include <tuple>

namespace trimkit::tess {
namespace {

// De Casteljau along one row of n+1 points with stride `stride`, in place:
// on return `left` and `right` hold the control points of [0,s] and [s,1].
void casteljau_split(const Eigen::Vector4d* row, int n, int stride, double s,
                     Eigen::Vector4d* left, Eigen::Vector4d* right) {
    Eigen::Vector4d work[geom::kMaxDegree + 1];
    for (int i = 0; i <= n; ++i) work[i] = row[i * stride];
    left[0] = work[0];
    right[n] = work[n];
    for (int r = 1; r <= n; ++r) {
        for (int i = 0; i <= n - r; ++i) work[i] = (1.0 - s) * work[i] + s * work[i + 1];
        left[r] = work[0];
        right[n - r] = work[n - r];
    }
}

}  // namespace

Eigen::Vector3d BezierPatch::evaluate(double s, double t) const {
    Eigen::Vector4d column[geom::kMaxDegree + 1];
    for (int i = 0; i <= p; ++i) column[i] = column_at(i, t);
    return along_s(column, s);
}

Eigen::Vector4d BezierPatch::column_at(int i, double t) const {
    Eigen::Vector4d work[geom::kMaxDegree + 1];
    for (int j = 0; j <= q; ++j) work[j] = point(i, j);
    for (int r = 1; r <= q; ++r)
        for (int j = 0; j <= q - r; ++j) work[j] = (1.0 - t) * work[j] + t * work[j + 1];
    return work[0];
}

Eigen::Vector3d BezierPatch::along_s(const Eigen::Vector4d* columns, double s) const {
    Eigen::Vector4d column[geom::kMaxDegree + 1];
    for (int i = 0; i <= p; ++i) column[i] = columns[i];
    for (int r = 1; r <= p; ++r)
        for (int i = 0; i <= p - r; ++i) column[i] = (1.0 - s) * column[i] + s * column[i + 1];
    return column[0].head<3>() / column[0][3];
}

BezierPatch bezier_patch(const geom::NurbsSurface& bezier) {
    BezierPatch patch;
    patch.p = bezier.degree_u();
    patch.q = bezier.degree_v();
    assert(bezier.count_u() == patch.p + 1 && bezier.count_v() == patch.q + 1 &&
           "bezier_patch needs a patch from NurbsSurface::bezier_patches");
    std::tie(patch.u0, patch.u1) = bezier.domain_u();
    std::tie(patch.v0, patch.v1) = bezier.domain_v();
    patch.Pw.resize(static_cast<size_t>(patch.p + 1) * (patch.q + 1));
    for (int i = 0; i <= patch.p; ++i)
        for (int j = 0; j <= patch.q; ++j) {
            const double w = bezier.weight(i, j);
            patch.Pw[i * (patch.q + 1) + j] << w * bezier.point(i, j), w;
        }
    return patch;
}

std::pair<BezierPatch, BezierPatch> split_u(const BezierPatch& patch, double s) {
    BezierPatch a = patch, b = patch;
    const double u = patch.u0 + s * (patch.u1 - patch.u0);
    a.u1 = u;
    b.u0 = u;
    Eigen::Vector4d left[geom::kMaxDegree + 1], right[geom::kMaxDegree + 1];
    for (int j = 0; j <= patch.q; ++j) {
        casteljau_split(&patch.Pw[j], patch.p, patch.q + 1, s, left, right);
        for (int i = 0; i <= patch.p; ++i) {
            a.Pw[i * (patch.q + 1) + j] = left[i];
            b.Pw[i * (patch.q + 1) + j] = right[i];
        }
    }
    return {std::move(a), std::move(b)};
}

std::pair<BezierPatch, BezierPatch> split_v(const BezierPatch& patch, double t) {
    BezierPatch a = patch, b = patch;
    const double v = patch.v0 + t * (patch.v1 - patch.v0);
    a.v1 = v;
    b.v0 = v;
    for (int i = 0; i <= patch.p; ++i) {
        const int row = i * (patch.q + 1);
        casteljau_split(&patch.Pw[row], patch.q, 1, t, &a.Pw[row], &b.Pw[row]);
    }
    return {std::move(a), std::move(b)};
}

BezierPatch restrict_patch(const BezierPatch& patch, double u0, double u1, double v0,
                           double v1) {
    BezierPatch r = patch;
    if (u0 > r.u0) r = split_u(r, (u0 - r.u0) / (r.u1 - r.u0)).second;
    r.u0 = std::max(u0, patch.u0);
    if (u1 < r.u1) r = split_u(r, (u1 - r.u0) / (r.u1 - r.u0)).first;
    r.u1 = std::min(u1, patch.u1);
    if (v0 > r.v0) r = split_v(r, (v0 - r.v0) / (r.v1 - r.v0)).second;
    r.v0 = std::max(v0, patch.v0);
    if (v1 < r.v1) r = split_v(r, (v1 - r.v0) / (r.v1 - r.v0)).first;
    r.v1 = std::min(v1, patch.v1);
    return r;
}

}  // namespace trimkit::tess
