#include "tess/revolution_error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace trimkit::tess {
namespace {

// Derivation of the bound (re-derived; the sagitta is the only formula taken over).
// Cylindrical coordinates about the axis: a point is (rho e_r(phi), z). A triangle
// vertex V_k = R_phi_k C(b_k) has meridian point m_k = (rho_k, z_k) = C(b_k). A point
// of the triangle, P = sum lambda_k V_k:
//  1. Its height is z_bar = sum lambda_k z_k; its horizontal part sum lambda_k rho_k
//     e_r(phi_k) has length rho_P <= rho_bar = sum lambda_k rho_k, and its component
//     along e_r of the middle angle is >= rho_bar cos(theta/2), because every phi_k
//     lies within theta/2 of it (the cell's angles form one interval theta < pi: a
//     cell lies in one Bezier piece of a rational circle with positive weights).
//     So rho_bar cos(theta/2) <= rho_P <= rho_bar, and P's angle phi_P lies in the
//     cell's interval.
//  2. m_bar = (rho_bar, z_bar) is a convex combination of meridian points of the
//     cell. Straight meridian: m_bar lies on it, so X = R_phi_P C(b) with C(b) = m_bar
//     is a point of S and |P - X| = rho_bar - rho_P <= rho_max (1 - cos(theta/2)).
//     Circular meridian of radius r over an angle psi < pi: m_bar lies between the
//     arc and its chord, at a distance from the centre in [r cos(psi/2), r]; the
//     point of the meridian circle in the direction of (rho_P, z_bar) from the centre
//     is within |rho_P - rho_bar| + r (1 - cos(psi/2)) of P, on the surface's circle
//     of revolution. rho_max <= max rho at the cell's ends + r (1 - cos(psi/2)) (the
//     arc lies within the sagitta of its chord).
//  3. Vertices off S by up to delta (trim crossings) move P by at most delta, so the
//     trim-aware shares of kd_subdivision add as for bilinear_error.
//  4. The other direction (points of S over the cell near the triangles): map a mesh
//     point P to (phi_P, the meridian point nearest to (rho_P, z_bar)). The map is
//     continuous; on the cell's sides it sends the chords of the rows (circles) and
//     of the meridians onto the sides of the cell on S monotonically, so it has degree
//     1 on the boundary and reaches every point X of S over the cell; then |P - X| is
//     the distance of 2. Hence the bound holds both ways.

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Planned splits closer than this to a side make slivers; the plan is a hint only.
constexpr double kMinPlannedSplit = 0.05;
// Bisection steps for the parameter of a planned angle (2^-30 of the cell).
constexpr int kSplitBisections = 30;
// A cell whose two half angles sum to its angle within this is monotone in angle.
constexpr double kAngleSumSlack = 1e-9;
// Rows at fractions of the angle direction used to find the axis, and the grid of
// samples that must confirm the shape.
constexpr std::array<double, 3> kRowFractions = {0.1, 0.5, 0.9};
constexpr std::array<double, 5> kAxisRows = {0.05, 0.27, 0.5, 0.73, 0.95};
constexpr int kCheckSteps = 18;

// Circle through a, b, c: centre, unit normal and radius; false if collinear.
bool circle_through(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                    Eigen::Vector3d* centre, Eigen::Vector3d* normal, double* radius) {
    const Eigen::Vector3d u = b - a, v = c - a, w = u.cross(v);
    const double w2 = w.squaredNorm();
    if (!(w2 > 1e-24 * u.squaredNorm() * v.squaredNorm()) || !(w2 > 0.0)) return false;
    // Circumcentre: a + (|u|^2 v x w + |v|^2 w x u) / (2 |w|^2).
    *centre = a + (u.squaredNorm() * v.cross(w) + v.squaredNorm() * w.cross(u)) / (2.0 * w2);
    *normal = w / std::sqrt(w2);
    *radius = (a - *centre).norm();
    return std::isfinite(*radius);
}

// Circle through three points of the plane; false if collinear.
bool circle_through(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                    Eigen::Vector2d* centre, double* radius) {
    Eigen::Vector3d c3, n3;
    if (!circle_through(Eigen::Vector3d(a.x(), a.y(), 0), Eigen::Vector3d(b.x(), b.y(), 0),
                        Eigen::Vector3d(c.x(), c.y(), 0), &c3, &n3, radius))
        return false;
    *centre = c3.head<2>();
    return true;
}

// S at fractions (fa, fb) of its domain, fa along the angle direction.
Eigen::Vector3d sample(const geom::NurbsSurface& S, int angle_dir, double fa, double fb) {
    const auto [u0, u1] = S.domain_u();
    const auto [v0, v1] = S.domain_v();
    const double fu = angle_dir == 0 ? fa : fb, fv = angle_dir == 0 ? fb : fa;
    return S.evaluate(u0 + fu * (u1 - u0), v0 + fv * (v1 - v0));
}

double surface_size(const geom::NurbsSurface& S) {
    Eigen::AlignedBox3d box;
    for (const Eigen::Vector3d& P : S.points()) box.extend(P);
    return box.diagonal().norm();
}

// The largest coordinate magnitude: files round coordinates to digits of it.
double coordinate_size(const geom::NurbsSurface& S) {
    double r = 0.0;
    for (const Eigen::Vector3d& P : S.points()) r = std::max(r, P.cwiseAbs().maxCoeff());
    return r;
}

// The axis from the widest circular row; false if no row is a circle.
bool find_axis(const geom::NurbsSurface& S, int angle_dir, RevolutionShape* shape) {
    double widest = 0.0;
    for (double fb : kAxisRows) {
        Eigen::Vector3d c, n;
        double r = 0.0;
        if (!circle_through(sample(S, angle_dir, kRowFractions[0], fb), sample(S, angle_dir, kRowFractions[1], fb),
                            sample(S, angle_dir, kRowFractions[2], fb), &c, &n, &r))
            continue;
        if (r > widest) widest = r, shape->origin = c, shape->axis = n;
    }
    return widest > 0.0;
}

// Every row of the check grid turns about the axis: its meridian point is constant.
bool rows_turn_about_axis(const geom::NurbsSurface& S, const RevolutionShape& shape, double eps) {
    for (int j = 0; j <= kCheckSteps; ++j) {
        const double fb = double(j) / kCheckSteps;
        const Eigen::Vector2d m0 = shape.meridian(sample(S, shape.angle_dir, 0.0, fb));
        for (int i = 1; i <= kCheckSteps; ++i)
            if ((shape.meridian(sample(S, shape.angle_dir, double(i) / kCheckSteps, fb)) - m0).norm() > eps)
                return false;
    }
    return true;
}

// The meridian is a line or a circle (checked on kCheckSteps + 1 points).
bool fit_meridian(const geom::NurbsSurface& S, RevolutionShape* shape, bool circle, double eps) {
    std::vector<Eigen::Vector2d> m;
    for (int j = 0; j <= kCheckSteps; ++j) m.push_back(shape->meridian(sample(S, shape->angle_dir, 0.0, double(j) / kCheckSteps)));
    if (!circle) {
        const Eigen::Vector2d a = m.front(), d = m.back() - m.front();
        if (!(d.norm() > eps)) return false;
        const Eigen::Vector2d n = Eigen::Vector2d(-d.y(), d.x()).normalized();
        for (const Eigen::Vector2d& p : m)
            if (std::abs((p - a).dot(n)) > eps) return false;
        shape->circle_meridian = false;
        return true;
    }
    const int third = kCheckSteps / 3;
    if (!circle_through(m[0], m[third], m[2 * third], &shape->centre, &shape->radius)) return false;
    for (const Eigen::Vector2d& p : m)
        if (std::abs((p - shape->centre).norm() - shape->radius) > eps) return false;
    shape->circle_meridian = true;
    return true;
}

// Unsigned angle between a - centre and b - centre in [0, pi].
double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return std::atan2(a.cross(b).norm(), a.dot(b));
}
double angle_between(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return std::atan2(std::abs(a.x() * b.y() - a.y() * b.x()), a.dot(b));
}

// Horizontal vector from the axis to P.
Eigen::Vector3d radial_of(const RevolutionShape& shape, const Eigen::Vector3d& P) {
    const Eigen::Vector3d d = P - shape.origin;
    return d - d.dot(shape.axis) * shape.axis;
}

// The cell's points in its own terms: x along the angle direction, y along the meridian.
struct CellView {
    const RevolutionShape& shape;
    const BezierPatch& patch;
    Eigen::Vector3d at(double x, double y) const {
        return shape.angle_dir == 0 ? patch.evaluate(x, y) : patch.evaluate(y, x);
    }
};

// Points of one line of the cell, bit for bit as CellView::at gives them, with what
// does not change along the line computed once (the bisections of parameter_of_angle
// evaluate a line some 30 times): the row at y = `fixed` (x runs) or the meridian at
// x = 0 (y runs). BezierPatch::evaluate combines rows along t first, then along s; a
// line at fixed t keeps its rows' points, and at s = 0 or 1 the combination along s is
// the first or last row's point exactly.
class CellLine {
public:
    CellLine(const CellView& cell, bool row, double fixed) : cell_(cell) {
        const BezierPatch& patch = cell.patch;
        const bool t_fixed = row == (cell.shape.angle_dir == 0);  // else s is fixed
        const double t = row ? fixed : 0.0, s = row ? fixed : 0.0;
        if (t_fixed) {
            mode_ = Mode::kRows;
            for (int i = 0; i <= patch.p; ++i) rows_[i] = patch.column_at(i, t);
        } else if (s == 0.0 || s == 1.0) {
            mode_ = Mode::kOneRow;
            row_ = s == 0.0 ? 0 : patch.p;
        } else {
            mode_ = Mode::kWhole;
            fixed_ = s;
        }
    }
    Eigen::Vector3d at(double r) const {
        const BezierPatch& patch = cell_.patch;
        switch (mode_) {
        case Mode::kRows: return patch.along_s(rows_, r);
        case Mode::kOneRow: {
            const Eigen::Vector4d h = patch.column_at(row_, r);
            return h.head<3>() / h[3];
        }
        default: return patch.evaluate(fixed_, r);
        }
    }

private:
    enum class Mode { kRows, kOneRow, kWhole };
    const CellView& cell_;
    Mode mode_ = Mode::kWhole;
    Eigen::Vector4d rows_[geom::kMaxDegree + 1];
    int row_ = 0;
    double fixed_ = 0.0;
};

// Angle of a monotone arc whose directions (from the centre) at its start, middle and
// end are given, or infinity when its halves do not add up (not monotone, or beyond pi).
template <class V>
double monotone_angle(const V& start, const V& middle, const V& end) {
    const double whole = angle_between(start, end), first = angle_between(start, middle),
                 second = angle_between(middle, end);
    if (std::abs(first + second - whole) > kAngleSumSlack * std::max(1.0, whole) || !(whole < kMaxCellAngle))
        return kInfinity;
    return whole;
}

// Local parameter where angle_from_start reaches `target` (monotone, by bisection).
template <class Angle>
double parameter_of_angle(const Angle& angle_from_start, double target) {
    double lo = 0.0, hi = 1.0;
    for (int k = 0; k < kSplitBisections; ++k) {
        const double mid = 0.5 * (lo + hi);
        (angle_from_start(mid) < target ? lo : hi) = mid;
    }
    return std::clamp(0.5 * (lo + hi), kMinPlannedSplit, 1.0 - kMinPlannedSplit);
}

// Pieces an arc of angle `angle` and radius `radius` needs for sagittas <= budget.
double pieces(double angle, double radius, double budget) {
    if (!(budget > 0.0)) return 2.0;
    if (radius <= budget) return 1.0;
    const double max_angle = 2.0 * std::acos(1.0 - budget / radius);
    return std::max(1.0, std::ceil(angle / max_angle * (1.0 - 1e-12)));
}

double sagitta(double radius, double angle) { return radius * (1.0 - std::cos(0.5 * angle)); }

// ---- Recognition from the control net (any kind; exact up to eps) ----
// A rational Bezier patch of degree 2 along a whose columns j (fixed b index) are
//   (1) weights w_ij = u_i v_j (w_ij / w_0j the same for every j),
//   (2) circular arcs about one axis: P_0j and P_2j at the same (rho, z), P_1j on the
//       bisecting half-plane at the same z and rho / cos(alpha), alpha half the arc's
//       angle, u_1 / sqrt(u_0 u_2) = cos(alpha) (the circle conditions, [PT] Sec. 7.5),
//       all turning the same way from one half-plane, or all on the axis (poles),
// is R_phi(a) C(b) with C the column a = 0: row j is P_0j turned by phi(a), phi the
// same for every row (it depends on u and alpha only), and the rational sum over j
// commutes with the rotation (re-derived from [PT] Sec. 8.5, Algorithm A8.1). Its
// meridian C lies on a line when the m(P_0j) are collinear (convex hull), and on a
// circle when the column is a degree-2 arc with the same circle conditions in (rho, z).

// Relative misfit of the weight conditions (files print weights to ~10 digits). A
// middle weight off by a relative d moves the arc by at most d |P1 - C| <= d size
// (dC/dw1 = B1 (P1 - C) / W), so the shape's slack adds kWeightTolerance x size.
constexpr double kWeightTolerance = 1e-7;

// Circle centre of the arc with control points A0, A1, A2 (tangent at A0 and A2
// meeting at A1): C = A1 + (M - A1) |A1 A0|^2 / |A1 M|^2, M the chord's midpoint.
template <class V>
bool arc_centre(const V& A0, const V& A1, const V& A2, V* centre) {
    const V d = 0.5 * (A0 + A2) - A1;
    if (!(d.squaredNorm() > 0.0)) return false;
    *centre = A1 + d * ((A0 - A1).squaredNorm() / d.squaredNorm());
    return centre->allFinite();
}

struct NetColumn {
    Eigen::Vector3d A[3];
    double w[3];
};

NetColumn column(const BezierPatch& patch, int angle_dir, int j) {
    NetColumn c;
    for (int i = 0; i < 3; ++i) {
        const int a = angle_dir == 0 ? i : j, b = angle_dir == 0 ? j : i;
        c.A[i] = patch.euclidean(a, b);
        c.w[i] = patch.point(a, b)[3];
    }
    return c;
}

// Checks (1) and (2) on every column of the patch; `turn` is the sign of the rows'
// rotation about the axis, fixed by the first arc met (0 before).
bool rows_are_arcs(const RevolutionShape& shape, const BezierPatch& patch, double eps, double* turn) {
    const int columns = (shape.angle_dir == 0 ? patch.q : patch.p) + 1;
    const NetColumn first = column(patch, shape.angle_dir, 0);
    Eigen::Vector3d start_dir = Eigen::Vector3d::Zero();
    for (int j = 0; j < columns; ++j) {
        const NetColumn c = column(patch, shape.angle_dir, j);
        for (int i = 0; i < 3; ++i)
            if (std::abs(c.w[i] / c.w[0] - first.w[i] / first.w[0]) > kWeightTolerance * first.w[i] / first.w[0])
                return false;
        const Eigen::Vector2d m0 = shape.meridian(c.A[0]), m2 = shape.meridian(c.A[2]);
        if ((m0 - m2).norm() > eps || std::abs(shape.meridian(c.A[1]).y() - m0.y()) > eps) return false;
        if (m0.x() <= eps) {
            if ((c.A[1] - c.A[0]).norm() > eps || (c.A[2] - c.A[0]).norm() > eps) return false;
            continue;
        }
        const Eigen::Vector3d d0 = c.A[0] - shape.origin, d2 = c.A[2] - shape.origin;
        const Eigen::Vector3d r0 = d0 - d0.dot(shape.axis) * shape.axis, r2 = d2 - d2.dot(shape.axis) * shape.axis;
        const double sign = r0.cross(r2).dot(shape.axis) >= 0.0 ? 1.0 : -1.0;
        if (*turn == 0.0) *turn = sign;
        if (sign != *turn) return false;
        if (start_dir.isZero()) start_dir = r0.normalized();
        if ((r0.normalized() - start_dir).norm() > kWeightTolerance) return false;
        const double two_alpha = angle_between(r0, r2);
        if (!(two_alpha < kMaxCellAngle)) return false;
        const double ca = std::cos(0.5 * two_alpha);
        const Eigen::Vector3d expected =
            shape.origin + m0.y() * shape.axis + (r0 + r2).normalized() * (m0.x() / ca);
        if ((c.A[1] - expected).norm() > eps) return false;
        if (std::abs(c.w[1] / std::sqrt(c.w[0] * c.w[2]) - ca) > kWeightTolerance) return false;
    }
    return true;
}

// The patch's meridian (column a = 0) on a line, or on the shape's circle (fixed by
// the first circular patch when `circle` is asked for).
bool meridian_fits(RevolutionShape* shape, const BezierPatch& patch, bool circle, double eps) {
    const int n = shape->angle_dir == 0 ? patch.q : patch.p;
    std::vector<Eigen::Vector2d> m;
    std::vector<double> v;
    for (int j = 0; j <= n; ++j) {
        const int a = shape->angle_dir == 0 ? 0 : j, b = shape->angle_dir == 0 ? j : 0;
        m.push_back(shape->meridian(patch.euclidean(a, b)));
        v.push_back(patch.point(a, b)[3]);
    }
    if (!circle) {
        const Eigen::Vector2d d = m.back() - m.front();
        if (!(d.norm() > eps)) return n == 0;
        const Eigen::Vector2d normal = Eigen::Vector2d(-d.y(), d.x()).normalized();
        for (const Eigen::Vector2d& x : m)
            if (std::abs((x - m.front()).dot(normal)) > eps) return false;
        return true;
    }
    if (n != 2) return false;
    if (shape->radius == 0.0) {
        if (!arc_centre(m[0], m[1], m[2], &shape->centre)) return false;
        shape->radius = (m[0] - shape->centre).norm();
    }
    const Eigen::Vector2d e0 = m[0] - shape->centre, e2 = m[2] - shape->centre;
    if (std::abs(e0.norm() - shape->radius) > eps || std::abs(e2.norm() - shape->radius) > eps) return false;
    const double two_beta = angle_between(e0, e2);
    if (!(two_beta < kMaxCellAngle)) return false;
    const double cb = std::cos(0.5 * two_beta);
    const Eigen::Vector2d expected = shape->centre + (e0 + e2).normalized() * (shape->radius / cb);
    return (m[1] - expected).norm() <= eps && std::abs(v[1] / std::sqrt(v[0] * v[2]) - cb) <= kWeightTolerance;
}

// The axis from the first arc of the first patch with a row off the axis.
bool net_axis(const std::vector<BezierPatch>& patches, int angle_dir, RevolutionShape* shape) {
    for (const BezierPatch& patch : patches) {
        const int columns = (angle_dir == 0 ? patch.q : patch.p) + 1;
        for (int j = 0; j < columns; ++j) {
            const NetColumn c = column(patch, angle_dir, j);
            const Eigen::Vector3d n = (c.A[0] - c.A[1]).cross(c.A[2] - c.A[1]);
            Eigen::Vector3d centre;
            if (!(n.norm() > 0.0) || !arc_centre(c.A[0], c.A[1], c.A[2], &centre)) continue;
            shape->axis = n.normalized();
            shape->origin = centre;
            return true;
        }
    }
    return false;
}

std::optional<RevolutionShape> shape_from_net(const geom::NurbsSurface& S, double eps, double size) {
    std::vector<BezierPatch> patches;
    for (const geom::NurbsSurface& b : S.bezier_patches()) patches.push_back(bezier_patch(b));
    for (int angle_dir : {0, 1}) {
        if ((angle_dir == 0 ? S.degree_u() : S.degree_v()) != 2) continue;
        for (bool circle : {false, true}) {
            RevolutionShape shape;
            shape.angle_dir = angle_dir;
            shape.slack = eps + kWeightTolerance * size;
            shape.circle_meridian = circle;
            if (!net_axis(patches, angle_dir, &shape)) break;
            double turn = 0.0;
            bool ok = true;
            for (const BezierPatch& patch : patches)
                if (!rows_are_arcs(shape, patch, eps, &turn) || !meridian_fits(&shape, patch, circle, eps)) {
                    ok = false;
                    break;
                }
            if (ok) return shape;
        }
    }
    return std::nullopt;
}

}  // namespace

Eigen::Vector2d RevolutionShape::meridian(const Eigen::Vector3d& P) const {
    const Eigen::Vector3d d = P - origin;
    const double z = d.dot(axis);
    return {(d - z * axis).norm(), z};
}

std::optional<RevolutionShape> revolution_shape(const geom::NurbsSurface& S, const std::string& kind) {
    const bool line = kind == "cylinder" || kind == "cone", circle = kind == "sphere" || kind == "torus";
    const double size = surface_size(S);
    if (!(size > 0.0) || !std::isfinite(size)) return std::nullopt;
    // Coordinates far from the origin carry the file's rounding of their digits.
    const double eps = kShapeFitTolerance * (size + coordinate_size(S));
    // Any rational surface whose control net proves it (B-spline faces of CAD files
    // are often exact cylinders and tori); else the analytic kinds, found by samples.
    if (S.is_rational())
        if (std::optional<RevolutionShape> shape = shape_from_net(S, eps, size)) return shape;
    if (!line && !circle && kind != "revolution") return std::nullopt;
    for (int angle_dir : {0, 1}) {
        RevolutionShape shape;
        shape.angle_dir = angle_dir;
        shape.slack = eps;
        if (!find_axis(S, angle_dir, &shape) || !rows_turn_about_axis(S, shape, eps)) continue;
        if (!circle && fit_meridian(S, &shape, false, eps)) return shape;
        if (!line && fit_meridian(S, &shape, true, eps)) return shape;
    }
    return std::nullopt;
}

BilinearError revolution_error(const RevolutionShape& shape, const BezierPatch& patch, double tolerance) {
    BilinearError result;
    result.bound = kInfinity;
    const CellView cell{shape, patch};
    const Eigen::Vector2d m0 = shape.meridian(cell.at(0.0, 0.0)), m1 = shape.meridian(cell.at(0.0, 1.0));
    const Eigen::Vector2d mid = shape.meridian(cell.at(0.0, 0.5));

    // Meridian term (0 on a straight meridian) and the largest distance from the axis.
    double psi = 0.0, e_b = 0.0;
    const Eigen::Vector2d from_centre[3] = {m0 - shape.centre, mid - shape.centre, m1 - shape.centre};
    if (shape.circle_meridian) {
        psi = monotone_angle(from_centre[0], from_centre[1], from_centre[2]);
        if (!std::isfinite(psi)) return result;
        e_b = sagitta(shape.radius, psi);
    } else if (std::min(m0.x(), m1.x()) > shape.slack) {
        // The meridian line must not cross the axis inside the cell (rho is |linear|
        // there): then the three points are not collinear in (rho, z), or mid is on it.
        const Eigen::Vector2d d = m1 - m0;
        const double off = std::abs(d.x() * (mid - m0).y() - d.y() * (mid - m0).x());
        if (off > 1e-6 * d.squaredNorm() || mid.x() <= shape.slack) return result;
    }
    const double rho_max = std::max({m0.x(), m1.x(), mid.x()}) + e_b;

    // Angle term, measured on the row farthest from the axis.
    const double y_ref = m1.x() > m0.x() ? (mid.x() > m1.x() ? 0.5 : 1.0) : (mid.x() > m0.x() ? 0.5 : 0.0);
    double theta = 0.0;
    const CellLine row(cell, true, y_ref);
    const Eigen::Vector3d row_start = radial_of(shape, row.at(0.0));
    if (row_start.norm() > shape.slack) {
        theta = monotone_angle(row_start, radial_of(shape, row.at(0.5)), radial_of(shape, row.at(1.0)));
        if (!std::isfinite(theta)) return result;
    }
    const double e_a = sagitta(rho_max, theta);
    result.bound = e_a + e_b + shape.slack;

    // Split across the larger term, planned so that the pieces meet the tolerance.
    const bool along_angle = e_a >= e_b;
    const double k = along_angle ? pieces(theta, rho_max, tolerance - e_b - shape.slack)
                                 : pieces(psi, shape.radius, tolerance - e_a - shape.slack);
    const double fraction = k >= 2.0 ? std::floor(k / 2.0) / k : 0.5;
    double split = 0.5;
    if (along_angle && theta > 0.0) {
        split = parameter_of_angle([&](double x) { return angle_between(row_start, radial_of(shape, row.at(x))); },
                                   fraction * theta);
    } else if (!along_angle && psi > 0.0) {
        const CellLine meridian(cell, false, 0.0);
        split = parameter_of_angle(
            [&](double y) {
                return angle_between(from_centre[0], Eigen::Vector2d(shape.meridian(meridian.at(y)) - shape.centre));
            },
            fraction * psi);
    }
    result.split_in_u = along_angle == (shape.angle_dir == 0);
    result.split = split;
    return result;
}

}  // namespace trimkit::tess
