// Curve entities of IgesReader: 100 circular arc, 102 composite curve, 104 conic
// arc, 106 copious data (forms 1-3, 11-13, 63), 110 line, 112 parametric spline,
// 126 rational B-spline curve. Each becomes exact NURBS in model space (the
// entity's own transform applied); 102 keeps its pieces separate.
#include <algorithm>
#include <cmath>

#include "geom/analytic_curves.h"
#include "geom/bspline_basis.h"
#include "geom/error.h"
#include "io/iges_reader.h"

namespace trimkit::io {
namespace {

using geom::NurbsCurve3d;
using Eigen::Vector3d;

constexpr double kTwoPi = 6.283185307179586476925286766559;
// Relative distance below which an arc's start and end points coincide (a
// full circle) and polyline points are duplicates: far above the rounding of
// coordinates printed with 10+ digits, far below any real feature.
constexpr double kCoincidentRelative = 1e-10;

NurbsCurve3d arc_100(IgesParameterCursor& c) {
    double zt = c.real_or("ZT", 0);
    double x1 = c.real("X1"), y1 = c.real("Y1");
    double x2 = c.real("X2"), y2 = c.real("Y2");
    double x3 = c.real("X3"), y3 = c.real("Y3");
    const double r = std::hypot(x2 - x1, y2 - y1);
    if (!(r > 0)) c.fail("circular arc has radius 0");
    double t0 = std::atan2(y2 - y1, x2 - x1);
    double t1 = std::atan2(y3 - y1, x3 - x1);
    const double scale = std::max({r, std::fabs(x1), std::fabs(y1)});
    const bool closed = std::hypot(x3 - x2, y3 - y2) <= kCoincidentRelative * scale;
    if (closed) {
        t1 = t0 + kTwoPi;
    } else {
        while (t1 <= t0) t1 += kTwoPi;
    }
    return geom::circular_arc(Vector3d(x1, y1, zt), Vector3d::UnitX(), Vector3d::UnitY(), r, t0, t1);
}

// Implicit conic A x² + B xy + C y² + D x + E y + F = 0 in the plane z = ZT.
NurbsCurve3d conic_104(IgesParameterCursor& c) {
    const double A = c.real_or("A", 0), B = c.real_or("B", 0), C = c.real_or("C", 0);
    const double D = c.real_or("D", 0), E = c.real_or("E", 0), F = c.real_or("F", 0);
    const double zt = c.real_or("ZT", 0);
    // Separate statements: the order of reads must be the file's order.
    const double x1 = c.real("X1"), y1 = c.real("Y1");
    const double x2 = c.real("X2"), y2 = c.real("Y2");
    const Eigen::Vector2d P0(x1, y1), P2(x2, y2);
    const double scale = std::max({std::fabs(A), std::fabs(B), std::fabs(C)});
    if (!(scale > 0)) c.fail("conic has no quadratic term");
    const int form = c.entry().form;
    auto tangent = [&](const Eigen::Vector2d& p) {
        Eigen::Vector2d g(2 * A * p.x() + B * p.y() + D, B * p.x() + 2 * C * p.y() + E);
        return Eigen::Vector2d(-g.y(), g.x());
    };
    const double small = 1e-12 * scale;
    // Ellipse in standard position: exact elliptic arc on the eccentric angle.
    if ((form == 1 || form == 0) && std::fabs(B) <= small && std::fabs(D) <= small &&
        std::fabs(E) <= small && A * C > 0 && -F / A > 0) {
        const double a = std::sqrt(-F / A), b = std::sqrt(-F / C);
        double t0 = std::atan2(P0.y() / b, P0.x() / a);
        double t1 = std::atan2(P2.y() / b, P2.x() / a);
        if ((P2 - P0).norm() <= kCoincidentRelative * std::max(a, b)) {
            t1 = t0 + kTwoPi;
        } else {
            while (t1 <= t0) t1 += kTwoPi;
        }
        return geom::ellipse_arc(Vector3d(0, 0, zt), Vector3d::UnitX(), Vector3d::UnitY(), a, b, t0,
                                 t1);
    }
    // Other conics: the rational quadratic through both ends with the conic's
    // tangents there and a third conic point on the chord's perpendicular bisector.
    Eigen::Vector2d T0 = tangent(P0), T2 = tangent(P2);
    const Eigen::Vector2d chord = P2 - P0;
    if (T0.dot(chord) < 0) T0 = -T0;
    if (T2.dot(chord) < 0) T2 = -T2;
    const Eigen::Vector2d M = 0.5 * (P0 + P2);
    const Eigen::Vector2d n(-chord.y(), chord.x());
    // Q(M + s n) = qa s² + qb s + qc.
    auto Q = [&](const Eigen::Vector2d& p) {
        return A * p.x() * p.x() + B * p.x() * p.y() + C * p.y() * p.y() + D * p.x() + E * p.y() + F;
    };
    const double qa = A * n.x() * n.x() + B * n.x() * n.y() + C * n.y() * n.y();
    const double qb = 2 * A * M.x() * n.x() + B * (M.x() * n.y() + M.y() * n.x()) +
                      2 * C * M.y() * n.y() + D * n.x() + E * n.y();
    const double qc = Q(M);
    double s = 0;
    if (std::fabs(qa) > 1e-300) {
        const double disc = qb * qb - 4 * qa * qc;
        if (disc < 0) c.fail("conic arc: no conic point between the end points");
        const double r1 = (-qb + std::sqrt(disc)) / (2 * qa), r2 = (-qb - std::sqrt(disc)) / (2 * qa);
        s = std::fabs(r1) < std::fabs(r2) ? r1 : r2;
    } else if (std::fabs(qb) > 0) {
        s = -qc / qb;
    } else {
        c.fail("conic arc: degenerate data");
    }
    const Eigen::Vector2d Pon = M + s * n;
    auto to3 = [&](const Eigen::Vector2d& p, double z) { return Vector3d(p.x(), p.y(), z); };
    return geom::rational_quadratic_arc(to3(P0, zt), to3(T0, 0), to3(P2, zt), to3(T2, 0),
                                        to3(Pon, zt));
}

// Degree-1 curve through the points, parameterised by chord length; consecutive
// duplicates dropped.
NurbsCurve3d polyline(IgesParameterCursor& c, std::vector<Vector3d> pts) {
    double size = 0;
    for (const Vector3d& p : pts) size = std::max(size, p.cwiseAbs().maxCoeff());
    std::vector<Vector3d> kept;
    kept.reserve(pts.size());
    for (const Vector3d& p : pts)
        if (kept.empty() || (p - kept.back()).norm() > kCoincidentRelative * std::max(size, 1e-300))
            kept.push_back(p);
    if (kept.size() < 2) c.fail("polyline has fewer than 2 distinct points");
    std::vector<double> U;
    U.reserve(kept.size() + 2);
    U.push_back(0);
    double s = 0;
    U.push_back(0);
    for (std::size_t i = 1; i < kept.size(); ++i) {
        s += (kept[i] - kept[i - 1]).norm();
        U.push_back(s);
    }
    U.push_back(s);
    return NurbsCurve3d(1, std::move(U), std::move(kept));
}

NurbsCurve3d copious_106(IgesParameterCursor& c) {
    const int form = c.entry().form;
    const int ip = c.integer("interpretation flag IP");
    int per = 0;
    if (ip == 1) per = 2;
    else if (ip == 2) per = 3;
    else if (ip == 3) per = 6;
    else c.fail("copious data IP = " + std::to_string(ip) + ", expected 1, 2 or 3");
    if (!(form == 1 || form == 2 || form == 3 || form == 11 || form == 12 || form == 13 ||
          form == 63))
        c.fail("copious data form " + std::to_string(form) + " not supported");
    const int n = c.count("point count N", per, 1);
    double zt = 0;
    if (ip == 1) zt = c.real_or("ZT", 0);
    std::vector<Vector3d> pts;
    pts.reserve(static_cast<std::size_t>(n) + 1);
    for (int i = 0; i < n; ++i) {
        Vector3d p;
        p.x() = c.real_or("X", 0);
        p.y() = c.real_or("Y", 0);
        p.z() = ip == 1 ? zt : c.real_or("Z", 0);
        if (ip == 3) c.skip(3);
        pts.push_back(p);
    }
    if (form == 63 && !pts.empty()) pts.push_back(pts.front());
    return polyline(c, std::move(pts));
}

// Power-basis cubic on [0, h] (a + b s + c s² + d s³) to its Bézier points.
std::array<Vector3d, 4> cubic_to_bezier(const Vector3d& a, const Vector3d& b, const Vector3d& cc,
                                        const Vector3d& d, double h) {
    const Vector3d b1 = b * h, c1 = cc * h * h, d1 = d * h * h * h;
    return {a, a + b1 / 3.0, a + 2.0 * b1 / 3.0 + c1 / 3.0, a + b1 + c1 + d1};
}

NurbsCurve3d spline_112(IgesParameterCursor& c) {
    c.integer_or("CTYPE", 3);
    c.integer_or("H", 3);
    c.integer_or("NDIM", 3);
    const int n = c.count("segment count N", 13, 1);
    std::vector<double> T(static_cast<std::size_t>(n) + 1);
    for (double& t : T) t = c.real("breakpoint");
    for (int i = 0; i < n; ++i)
        if (!(T[i + 1] > T[i])) c.fail("breakpoints do not increase");
    std::vector<double> U;
    std::vector<Vector3d> P;
    U.insert(U.end(), 4, T[0]);
    for (int i = 0; i < n; ++i) {
        Vector3d A, B, C, D;
        for (int k = 0; k < 3; ++k) {
            A[k] = c.real_or("A", 0);
            B[k] = c.real_or("B", 0);
            C[k] = c.real_or("C", 0);
            D[k] = c.real_or("D", 0);
        }
        auto bz = cubic_to_bezier(A, B, C, D, T[i + 1] - T[i]);
        if (i == 0) P.push_back(bz[0]);
        P.push_back(bz[1]);
        P.push_back(bz[2]);
        P.push_back(bz[3]);
        U.insert(U.end(), i + 1 < n ? 3 : 4, T[i + 1]);
    }
    return NurbsCurve3d(3, std::move(U), std::move(P));
}

NurbsCurve3d bspline_126(IgesParameterCursor& c) {
    const int K = c.integer("upper index K");
    const int M = c.integer("degree M");
    if (M < 1 || M > geom::kMaxDegree)
        c.fail("degree " + std::to_string(M) + " is outside 1.." + std::to_string(geom::kMaxDegree));
    if (K < M) c.fail("upper index K = " + std::to_string(K) + " is below the degree " + std::to_string(M));
    // Knots, weights and points must all be present before anything is allocated.
    const long long need = static_cast<long long>(K) + M + 2 + 4LL * (K + 1) + 4;
    if (need > static_cast<long long>(c.remaining()))
        c.fail("K = " + std::to_string(K) + ", M = " + std::to_string(M) + " need " +
               std::to_string(need) + " parameters but only " + std::to_string(c.remaining()) +
               " follow");
    c.integer_or("PROP1", 0);
    c.integer_or("PROP2", 0);
    const int polynomial = c.integer_or("PROP3", 0);
    c.integer_or("PROP4", 0);
    const int nk = K + M + 2, np = K + 1;
    std::vector<double> U(nk);
    for (double& u : U) u = c.real("knot");
    for (int i = 0; i + 1 < nk; ++i)
        if (U[i + 1] < U[i])
            c.fail("knots decrease: T(" + std::to_string(i - M + 1) + ") = " +
                   geom::format_value(U[i + 1]) + " < " + geom::format_value(U[i]));
    std::vector<double> w(np);
    for (double& x : w) x = c.real_or("weight", 1.0);
    std::vector<Vector3d> P(np);
    for (Vector3d& p : P) p = c.point("control point");
    const double v0 = c.real_or("V0", U[M]), v1 = c.real_or("V1", U[K + 1]);
    w = iges_weights(std::move(w), polynomial != 0);
    NurbsCurve3d curve(M, std::move(U), std::move(P), std::move(w));
    auto [a, b] = curve.domain();
    const double tol = 1e-9 * std::max(1.0, b - a);
    double lo = std::max(a, std::min(v0, v1)), hi = std::min(b, std::max(v0, v1));
    if (hi - lo > tol && (lo > a + tol || hi < b - tol)) curve = curve.sub_curve(lo, hi);
    return curve;
}

}  // namespace

bool IgesReader::is_curve_type(int type) {
    switch (type) {
        case 100: case 102: case 104: case 106: case 110: case 112: case 126: case 130:
            return true;
        default:
            return false;
    }
}

const std::vector<geom::NurbsCurve3d>& IgesReader::curve(int de) {
    auto it = curve_cache_.find(de);
    if (it != curve_cache_.end()) return it->second;
    Nesting guard(*this, de);
    const IgesDirectoryEntry& e = entry_of(de);
    std::vector<NurbsCurve3d> out;
    try {
        IgesParameterCursor c(file_, file_.index_of(de));
        switch (e.type) {
            case 100: out.push_back(arc_100(c)); break;
            case 102: {
                const int n = c.count("curve count N", 1, 0);
                std::vector<int> parts(static_cast<std::size_t>(n));
                for (int& p : parts) p = c.pointer("constituent curve");
                for (int p : parts) {
                    if (p == 0) continue;
                    const int t = entry_of(p).type;
                    if (t == 116) continue;  // points may separate pieces; they add no curve
                    const std::vector<NurbsCurve3d>& piece = curve(p);
                    out.insert(out.end(), piece.begin(), piece.end());
                }
                if (out.empty()) c.fail("composite curve has no curve");
                break;
            }
            case 104: out.push_back(conic_104(c)); break;
            case 106: out.push_back(copious_106(c)); break;
            case 110: {
                Vector3d a = c.point("start point"), b = c.point("end point");
                out.push_back(geom::line_segment(a, b, 0.0, 1.0));
                break;
            }
            case 112: out.push_back(spline_112(c)); break;
            case 126: out.push_back(bspline_126(c)); break;
            case 130:
                warn_unsupported(de, "offset curve");
                c.fail("offset curve (130) not supported");
            default:
                c.fail("entity " + std::to_string(e.type) + " is not a curve");
        }
    } catch (const geom::InvalidInput& err) {
        fail(de, err.what());
    } catch (const geom::NumericalFailure& err) {
        fail(de, err.what());
    }
    if (e.transform != 0) {
        const Eigen::Affine3d T = transform_of(de);
        for (NurbsCurve3d& k : out) k = k.transformed(T);
    }
    return curve_cache_.emplace(de, std::move(out)).first->second;
}

std::vector<geom::NurbsCurve2d> IgesReader::parameter_curve(int de) {
    std::vector<geom::NurbsCurve2d> out;
    for (const NurbsCurve3d& k : curve(de)) out.push_back(geom::to_2d(k));
    return out;
}

std::vector<geom::NurbsCurve2d> IgesReader::parameter_curves(const std::vector<int>& des,
                                                             std::vector<std::string>* warnings) {
    std::vector<geom::NurbsCurve2d> joined;
    try {
        for (int de : des) {
            if (de == 0) continue;
            const std::vector<geom::NurbsCurve2d> pieces = parameter_curve(de);
            joined.insert(joined.end(), pieces.begin(), pieces.end());
        }
    } catch (const geom::ReadError& err) {
        warnings->push_back("parameter curve skipped: " + err.reason());
        return {};
    }
    return joined;
}

std::vector<double> iges_weights(std::vector<double> w, bool polynomial_flag) {
    // Relative spread below which equal weights mean "not rational".
    constexpr double kEqualWeights = 1e-12;
    bool rational = !polynomial_flag;
    if (rational) {
        rational = false;
        for (double x : w)
            if (std::fabs(x - w[0]) > kEqualWeights * std::fabs(w[0])) rational = true;
    }
    if (!rational) w.clear();
    return w;
}

}  // namespace trimkit::io
