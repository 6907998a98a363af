#include "tbp/triangle_intersection.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace trimkit::tbp {
namespace {

// Points where triangle t meets the plane (n, d0) (n . x = n . o): vertices on
// the plane and edge crossings. Returns the count (0..2; 3 if all on the plane).
int plane_section(const Triangle3& t, const Eigen::Vector3d& n, const Eigen::Vector3d& o, double eps,
                  Eigen::Vector3d out[3]) {
    double d[3];
    for (int i = 0; i < 3; ++i) {
        d[i] = n.dot(t[i] - o);
        if (std::abs(d[i]) <= eps) d[i] = 0.0;
    }
    if ((d[0] > 0 && d[1] > 0 && d[2] > 0) || (d[0] < 0 && d[1] < 0 && d[2] < 0)) return 0;
    if (d[0] == 0 && d[1] == 0 && d[2] == 0) return 3;
    int count = 0;
    for (int i = 0; i < 3; ++i) {
        if (d[i] == 0) out[count++] = t[i];
        const int j = (i + 1) % 3;
        if ((d[i] < 0 && d[j] > 0) || (d[i] > 0 && d[j] < 0)) {
            // Interpolate from the lexicographically smaller end, so the two
            // triangles sharing this edge compute the same point.
            int a = i, b = j;
            if (std::lexicographical_compare(t[j].data(), t[j].data() + 3, t[i].data(), t[i].data() + 3)) std::swap(a, b);
            out[count++] = t[a] + (t[b] - t[a]) * (d[a] / (d[a] - d[b]));
        }
        if (count == 2) break;
    }
    return count;
}

double size_of(const Triangle3& t) {
    return std::max({(t[1] - t[0]).norm(), (t[2] - t[1]).norm(), (t[0] - t[2]).norm()});
}

}  // namespace

bool triangle_intersection(const Triangle3& t1, const Triangle3& t2, Eigen::Vector3d& p, Eigen::Vector3d& q) {
    const Eigen::Vector3d n1 = (t1[1] - t1[0]).cross(t1[2] - t1[0]);
    const Eigen::Vector3d n2 = (t2[1] - t2[0]).cross(t2[2] - t2[0]);
    const double s1 = size_of(t1), s2 = size_of(t2);
    const double l1 = n1.norm(), l2 = n2.norm();
    if (l1 <= kPlaneRelativeTolerance * s1 * s1 || l2 <= kPlaneRelativeTolerance * s2 * s2) return false;
    Eigen::Vector3d a[3], b[3];
    const int na = plane_section(t1, n2, t2[0], kPlaneRelativeTolerance * l2 * std::max(s1, s2), a);
    if (na < 2) return false;
    const int nb = plane_section(t2, n1, t1[0], kPlaneRelativeTolerance * l1 * std::max(s1, s2), b);
    if (nb < 2 || na == 3 || nb == 3) return false;  // coplanar (or touching)
    const Eigen::Vector3d D = n1.cross(n2);
    double ta0 = D.dot(a[0]), ta1 = D.dot(a[1]), tb0 = D.dot(b[0]), tb1 = D.dot(b[1]);
    if (ta0 > ta1) std::swap(ta0, ta1), std::swap(a[0], a[1]);
    if (tb0 > tb1) std::swap(tb0, tb1), std::swap(b[0], b[1]);
    const double lo = std::max(ta0, tb0), hi = std::min(ta1, tb1);
    if (!(hi > lo)) return false;
    p = ta0 >= tb0 ? a[0] : b[0];
    q = ta1 <= tb1 ? a[1] : b[1];
    return p != q;
}

Eigen::Vector3d barycentric(const Triangle3& t, const Eigen::Vector3d& x) {
    const Eigen::Vector3d e0 = t[0] - t[2], e1 = t[1] - t[2], r = x - t[2];
    const double a = e0.dot(e0), b = e0.dot(e1), c = e1.dot(e1), d = e0.dot(r), e = e1.dot(r);
    const double det = a * c - b * b;
    Eigen::Vector3d l(det != 0 ? (c * d - b * e) / det : 1.0 / 3, det != 0 ? (a * e - b * d) / det : 1.0 / 3, 0);
    l[2] = 1 - l[0] - l[1];
    l = l.cwiseMax(0.0);
    return l / l.sum();
}

}  // namespace trimkit::tbp
