// Surface entities of IgesReader: 108 plane, 114 parametric spline surface, 118
// ruled surface, 120 surface of revolution, 122 tabulated cylinder, 128 rational
// B-spline surface, 190 plane, 192 cylinder, 194 cone, 196 sphere, 198 torus.
// Each becomes an exact NURBS surface (own transform applied) with the map from
// the entity's native parameters to the NURBS ones (IgesSurface). Unbounded
// surfaces take their extent from the boundary points of the face using them.
#include <algorithm>
#include <cmath>
#include <tuple>

#include "geom/analytic_surfaces.h"
#include "geom/bspline_basis.h"
#include "geom/extend_closed_surface.h"
#include "geom/error.h"
#include "io/boundary_extent.h"
#include "io/iges_reader.h"

namespace trimkit::io {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;
using geom::NurbsSurface;

constexpr double kPi = 3.14159265358979323846;
// Unbounded surfaces are built this much (relative) larger than their trims'
// extent, so trims near the edge stay strictly inside the domain.
constexpr double kHintMargin = 0.02;
// A 120's sweep within this (radians) past a whole turn is a whole turn: files print
// angles with 10 digits (OCCT's writer: -6.283185307 to 2.17e-09).
constexpr double kTurnRounding = 1e-7;

// The terminate angle of a 120 whose sweep is a whole turn up to rounding, made exact.
double whole_turn_snapped(double start, double terminate) {
    const double excess = std::fabs(terminate - start) - 2 * kPi;
    if (excess > 0 && excess <= kTurnRounding) return start + (terminate > start ? 2 * kPi : -2 * kPi);
    return terminate;
}

NurbsSurface bspline_128(IgesParameterCursor& c) {
    const int K1 = c.integer("upper index K1"), K2 = c.integer("upper index K2");
    const int M1 = c.integer("degree M1"), M2 = c.integer("degree M2");
    for (int m : {M1, M2})
        if (m < 1 || m > geom::kMaxDegree)
            c.fail("degree " + std::to_string(m) + " is outside 1.." + std::to_string(geom::kMaxDegree));
    if (K1 < M1 || K2 < M2)
        c.fail("upper indices K1 = " + std::to_string(K1) + ", K2 = " + std::to_string(K2) +
               " are below the degrees " + std::to_string(M1) + ", " + std::to_string(M2));
    // Each count alone must fit in what follows before their product is formed.
    if (K1 + M1 + 2LL > static_cast<long long>(c.remaining()) ||
        K2 + M2 + 2LL > static_cast<long long>(c.remaining()))
        c.fail("K1 = " + std::to_string(K1) + ", K2 = " + std::to_string(K2) + " need more parameters than the " +
               std::to_string(c.remaining()) + " that follow");
    const long long nu = K1 + 1LL, nv = K2 + 1LL;
    const long long need = 5 + (K1 + M1 + 2LL) + (K2 + M2 + 2LL) + 4 * nu * nv;
    if (need > static_cast<long long>(c.remaining()))
        c.fail("K1 = " + std::to_string(K1) + ", K2 = " + std::to_string(K2) + " need " +
               std::to_string(need) + " parameters but only " + std::to_string(c.remaining()) + " follow");
    c.integer_or("PROP1", 0);
    c.integer_or("PROP2", 0);
    const int polynomial = c.integer_or("PROP3", 0);
    c.integer_or("PROP4", 0);
    c.integer_or("PROP5", 0);
    auto knots = [&](long long n, const char* what) {
        std::vector<double> U(static_cast<std::size_t>(n));
        for (double& u : U) u = c.real(what);
        for (std::size_t i = 0; i + 1 < U.size(); ++i)
            if (U[i + 1] < U[i])
                c.fail(std::string(what) + "s decrease: " + geom::format_value(U[i + 1]) + " after " +
                       geom::format_value(U[i]));
        return U;
    };
    std::vector<double> U = knots(K1 + M1 + 2LL, "u knot");
    std::vector<double> V = knots(K2 + M2 + 2LL, "v knot");
    // The file lists weights and points with the first index (u) fastest.
    std::vector<double> w(static_cast<std::size_t>(nu * nv));
    for (long long j = 0; j < nv; ++j)
        for (long long i = 0; i < nu; ++i) w[i * nv + j] = c.real_or("weight", 1.0);
    std::vector<Vector3d> P(static_cast<std::size_t>(nu * nv));
    for (long long j = 0; j < nv; ++j)
        for (long long i = 0; i < nu; ++i) P[i * nv + j] = c.point("control point");
    const double u0 = c.real_or("U0", U[M1]), u1 = c.real_or("U1", U[K1 + 1]);
    const double v0 = c.real_or("V0", V[M2]), v1 = c.real_or("V1", V[K2 + 1]);
    w = iges_weights(std::move(w), polynomial != 0);
    NurbsSurface s(M1, M2, std::move(U), std::move(V), static_cast<int>(nu), static_cast<int>(nv),
                   std::move(P), std::move(w));
    // Restrict to the parameter range the file uses when it is a proper part.
    const auto [a0, a1] = s.domain_u();
    const auto [b0, b1] = s.domain_v();
    const double tu = 1e-9 * (a1 - a0), tv = 1e-9 * (b1 - b0);
    const double lu = std::max(a0, std::min(u0, u1)), hu = std::min(a1, std::max(u0, u1));
    const double lv = std::max(b0, std::min(v0, v1)), hv = std::min(b1, std::max(v0, v1));
    if (hu - lu > tu && hv - lv > tv &&
        (lu > a0 + tu || hu < a1 - tu || lv > b0 + tv || hv < b1 - tv))
        s = s.sub_surface(lu, hu, lv, hv);
    return s;
}

// Bicubic power basis patch to Bézier points: u^a = Σ_{i>=a} C(i,a)/C(3,a) B_i(u).
NurbsSurface spline_114(IgesParameterCursor& c) {
    c.integer_or("boundary type", 3);
    c.integer_or("patch type", 1);
    const int M = c.count("u segment count M", 1, 1), N = c.count("v segment count N", 1, 1);
    const long long need = (M + 1LL) + (N + 1LL) + 48LL * (M + 1LL) * (N + 1LL);
    if (need > static_cast<long long>(c.remaining()) + 48LL * (M + N + 1))
        c.fail("M = " + std::to_string(M) + ", N = " + std::to_string(N) + " need " +
               std::to_string(need) + " parameters but only " + std::to_string(c.remaining()) + " follow");
    std::vector<double> TU(M + 1), TV(N + 1);
    for (double& t : TU) t = c.real("u breakpoint");
    for (double& t : TV) t = c.real("v breakpoint");
    for (int i = 0; i < M; ++i)
        if (!(TU[i + 1] > TU[i])) c.fail("u breakpoints do not increase");
    for (int j = 0; j < N; ++j)
        if (!(TV[j + 1] > TV[j])) c.fail("v breakpoints do not increase");
    const int nu = 3 * M + 1, nv = 3 * N + 1;
    std::vector<Vector3d> P(static_cast<std::size_t>(nu) * nv, Vector3d::Zero());
    static const double Q[4][4] = {{1, 0, 0, 0}, {1, 1.0 / 3, 0, 0}, {1, 2.0 / 3, 1.0 / 3, 0}, {1, 1, 1, 1}};
    for (int i = 0; i < M; ++i) {
        for (int j = 0; j < N; ++j) {
            // Coefficients in the order A..S: s^a t^b with a fastest.
            double coef[3][4][4];
            for (int k = 0; k < 3; ++k)
                for (int b = 0; b < 4; ++b)
                    for (int a = 0; a < 4; ++a) coef[k][a][b] = c.real_or("coefficient", 0);
            const double h = TU[i + 1] - TU[i], g = TV[j + 1] - TV[j];
            for (int bi = 0; bi < 4; ++bi)
                for (int bj = 0; bj < 4; ++bj) {
                    Vector3d x = Vector3d::Zero();
                    for (int a = 0; a < 4; ++a)
                        for (int b = 0; b < 4; ++b) {
                            const double f = Q[bi][a] * Q[bj][b] * std::pow(h, a) * std::pow(g, b);
                            for (int k = 0; k < 3; ++k) x[k] += f * coef[k][a][b];
                        }
                    P[static_cast<std::size_t>(3 * i + bi) * nv + 3 * j + bj] = x;
                }
        }
        c.skip(48);  // the unused patch (i, N+1)
    }
    auto knots = [](const std::vector<double>& T) {
        std::vector<double> U(4, T.front());
        for (std::size_t k = 1; k + 1 < T.size(); ++k) U.insert(U.end(), 3, T[k]);
        U.insert(U.end(), 4, T.back());
        return U;
    };
    return NurbsSurface(3, 3, knots(TU), knots(TV), nu, nv, std::move(P));
}

// Orthonormal X, Y completing the unit axis A (X from ref when usable).
void frame(const Vector3d& A, const Vector3d* ref, Vector3d* X, Vector3d* Y) {
    Vector3d r;
    if (ref && (*ref - ref->dot(A) * A).norm() > 1e-9 * ref->norm()) {
        r = *ref - ref->dot(A) * A;
    } else {
        Vector3d t = std::fabs(A.x()) < 0.9 ? Vector3d::UnitX() : Vector3d::UnitY();
        r = t - t.dot(A) * A;
    }
    *X = r.normalized();
    *Y = A.cross(*X);
}

}  // namespace

bool IgesReader::is_surface_type(int type) {
    switch (type) {
        case 108: case 114: case 118: case 120: case 122: case 128: case 140:
        case 190: case 192: case 194: case 196: case 198:
            return true;
        default:
            return false;
    }
}

IgesSurface IgesReader::surface(int de, const BoundaryHint* hint) {
    Nesting guard(*this, de);
    const IgesDirectoryEntry& e = entry_of(de);
    IgesSurface out;
    // The hint is in model space; unbounded surfaces are sized in their own
    // definition space.
    const Eigen::Affine3d own = transform_of(de);
    std::vector<Vector3d> local;
    if (hint) {
        const Eigen::Affine3d inv = own.inverse();
        for (const Vector3d& p : *hint) local.push_back(inv * p);
    }
    auto single_curve = [&](int curve_de, const char* what) -> geom::NurbsCurve3d {
        const std::vector<geom::NurbsCurve3d>& k = curve(curve_de);
        if (k.size() != 1) fail(de, std::string(what) + " is a composite curve of " + std::to_string(k.size()) + " pieces");
        return k.front();
    };
    // The angle map of a 100 circular arc (built counter-clockwise on its angles,
    // so its NURBS domain is [θ0, θ1]); none for other curves.
    auto arc_angles = [&](int curve_de, const geom::NurbsCurve3d& g) -> std::optional<geom::ArcParameterMap> {
        if (entry_of(curve_de).type != 100) return std::nullopt;
        return geom::ArcParameterMap(g.domain().first, g.domain().second);
    };
    auto point_of = [&](IgesParameterCursor& c, const char* what, int type) -> Vector3d {
        const int p = c.pointer(what);
        if (p == 0) c.fail(std::string(what) + " is missing");
        if (entry_of(p).type != type)
            c.fail(std::string(what) + " points to entity " + std::to_string(entry_of(p).type) +
                   ", expected " + std::to_string(type));
        IgesParameterCursor q(file_, file_.index_of(p));
        Vector3d x = q.point(what);
        if (type == 116) x = transform_of(p) * x;
        else x = transform_of(p).linear() * x;
        return x;
    };
    // Extent of the local hint along directions (for unbounded surfaces).
    auto range = [&](const Vector3d& o, const Vector3d& d, double* lo, double* hi) {
        std::vector<double> t;
        t.reserve(local.size());
        for (const Vector3d& p : local) t.push_back((p - o).dot(d));
        std::tie(*lo, *hi) = padded_extent(t, kHintMargin);
    };
    try {
        IgesParameterCursor c(file_, file_.index_of(de));
        switch (e.type) {
            case 128:
                out.nurbs = bspline_128(c);
                out.kind = "bspline";
                out.map = IgesSurface::Map::kAffine;
                break;
            case 114:
                out.nurbs = spline_114(c);
                out.kind = "parametric_spline";
                out.map = IgesSurface::Map::kAffine;
                break;
            case 118: {
                const int c1 = c.pointer("first curve"), c2 = c.pointer("second curve");
                const int dir = c.integer_or("direction flag", 0);
                c.integer_or("developable flag", 0);
                if (c1 == 0 || c2 == 0) c.fail("ruled surface curve missing");
                geom::NurbsCurve3d a = single_curve(c1, "first ruled curve");
                geom::NurbsCurve3d b = single_curve(c2, "second ruled curve");
                if (dir == 1) b = b.reversed();
                out.nurbs = geom::ruled_surface(a, b);
                out.kind = "ruled";
                // Form 1 (equal relative parameter) is the NURBS's own map;
                // form 0 (equal relative arc length) is not affine: project.
                out.map = e.form == 1 ? IgesSurface::Map::kAffine : IgesSurface::Map::kNone;
                break;
            }
            case 120: {
                const int axis = c.pointer("axis"), gen = c.pointer("generatrix");
                const double sa = c.real("start angle");
                const double ta = whole_turn_snapped(sa, c.real("terminate angle"));
                if (axis == 0 || gen == 0) c.fail("surface of revolution without axis or generatrix");
                const geom::NurbsCurve3d line = single_curve(axis, "axis");
                const Vector3d p0 = line.evaluate(line.domain().first), p1 = line.evaluate(line.domain().second);
                if (!((p1 - p0).norm() > 0)) c.fail("axis line has zero length");
                const geom::NurbsCurve3d g = single_curve(gen, "generatrix");
                out.nurbs = geom::surface_of_revolution(g, p0, p1 - p0, sa, ta);
                out.kind = "revolution";
                out.map = IgesSurface::Map::kAngleV;
                out.angle.emplace(sa, ta);
                out.angle_u = arc_angles(gen, g);
                break;
            }
            case 122: {
                const int dir = c.pointer("directrix");
                const Vector3d L = c.point("generatrix end point");
                if (dir == 0) c.fail("tabulated cylinder without directrix");
                const geom::NurbsCurve3d d = single_curve(dir, "directrix");
                const auto [t0, t1] = d.domain();
                out.nurbs = geom::tabulated_cylinder(d, L - d.evaluate(t0), 0.0, 1.0);
                out.kind = "tabulated_cylinder";
                // IGES 5.3 Sec. 4.19: u ∈ [0,1] runs over the directrix domain.
                out.map = IgesSurface::Map::kAffine;
                out.su = t1 - t0;
                out.ou = t0;
                out.angle_u = arc_angles(dir, d);
                break;
            }
            case 108: {
                Vector3d n = c.point("normal coefficients A, B, C");
                const double D = c.real_or("D", 0);
                const int boundary = c.pointer("bounding curve");
                const Vector3d loc = c.point("location");
                if (!(n.norm() > 0)) c.fail("plane normal is zero");
                const double len = n.norm();
                n /= len;
                const Vector3d origin = loc - (loc.dot(n) - D / len) * n;
                if (local.empty() && boundary != 0) {
                    for (const auto& k : curve(boundary))
                        for (const auto& p : k.points()) local.push_back(p);
                }
                if (local.empty()) c.fail("unbounded plane has no boundary to size it");
                Vector3d X, Y;
                frame(n, nullptr, &X, &Y);
                double u0, u1, v0, v1;
                range(origin, X, &u0, &u1);
                range(origin, Y, &v0, &v1);
                out.nurbs = geom::plane_patch(origin, X, Y, u0, u1, v0, v1);
                out.kind = "plane";
                out.map = IgesSurface::Map::kNone;
                break;
            }
            case 190: {
                const Vector3d L = point_of(c, "location", 116);
                Vector3d N = point_of(c, "normal", 123);
                Vector3d R;
                bool has_ref = false;
                if (e.form == 1 && c.remaining() > 0) {
                    R = point_of(c, "reference direction", 123);
                    has_ref = true;
                }
                if (!(N.norm() > 0)) c.fail("plane normal is zero");
                N.normalize();
                Vector3d X, Y;
                frame(N, has_ref ? &R : nullptr, &X, &Y);
                if (local.empty()) c.fail("unbounded plane has no boundary to size it");
                double u0, u1, v0, v1;
                range(L, X, &u0, &u1);
                range(L, Y, &v0, &v1);
                out.nurbs = geom::plane_patch(L, X, Y, u0, u1, v0, v1);
                out.kind = "plane";
                out.map = has_ref ? IgesSurface::Map::kAffine : IgesSurface::Map::kNone;
                break;
            }
            case 192: case 194: case 196: case 198: {
                const Vector3d L = point_of(c, "location", 116);
                Vector3d A;
                double r1 = 0, r2 = 0;
                if (e.type == 196) {
                    r1 = c.real("radius");
                    A = c.remaining() > 0 ? point_of(c, "axis", 123) : Vector3d::UnitZ();
                } else {
                    A = point_of(c, "axis", 123);
                    r1 = c.real(e.type == 198 ? "major radius" : "radius");
                    if (e.type == 194 || e.type == 198) r2 = c.real(e.type == 194 ? "semi-angle" : "minor radius");
                }
                Vector3d R;
                bool has_ref = false;
                if (e.form == 1 && c.remaining() > 0) {
                    R = point_of(c, "reference direction", 123);
                    has_ref = true;
                }
                if (!(A.norm() > 0)) c.fail("axis is zero");
                A.normalize();
                Vector3d X, Y;
                frame(A, has_ref ? &R : nullptr, &X, &Y);
                if (local.empty()) c.fail("unbounded surface has no boundary to size it");
                double z0, z1;
                range(L, A, &z0, &z1);
                if (e.type == 192) {
                    out.nurbs = geom::cylinder_patch(L, A, X, r1, 0, 2 * kPi, z0, z1);
                    out.kind = "cylinder";
                } else if (e.type == 194) {
                    // The margin must not carry the range past the apex onto the other
                    // nappe: the apex would be an inner line of the domain, not its side
                    // (cone_with_apex_brep.igs: 84 000 triangles for one face at 1e-4).
                    const double t = std::tan(r2 * kPi / 180.0);
                    if (t != 0.0) {
                        const double apex = -r1 / t;
                        if (apex > z0 && apex < z1) (apex - z0 > z1 - apex ? z1 : z0) = apex;
                    }
                    out.nurbs = geom::cone_patch(L, A, X, r1, r2 * kPi / 180.0, 0, 2 * kPi, z0, z1);
                    out.kind = "cone";
                } else if (e.type == 196) {
                    out.nurbs = geom::sphere_patch(L, A, X, r1, 0, 2 * kPi, -kPi / 2, kPi / 2);
                    out.kind = "sphere";
                } else {
                    out.nurbs = geom::torus_patch(L, A, X, r1, r2, 0, 2 * kPi, -kPi, kPi);
                    out.kind = "torus";
                }
                out.map = IgesSurface::Map::kNone;
                break;
            }
            case 140: {
                // Offsets of surfaces of revolution whose generatrix is a line or
                // a circular arc are again such surfaces: the generatrix offset in
                // its meridian plane is a parallel line or a concentric arc.
                const Vector3d indicator = c.point("offset indicator");
                const double d = c.real("offset distance");
                const int base = c.pointer("surface");
                if (base == 0) c.fail("offset surface without base surface");
                if (entry_of(base).type != 120) {
                    warn_unsupported(de, "offset surface");
                    c.fail("offset of entity " + std::to_string(entry_of(base).type) +
                           " not supported (only of surfaces of revolution)");
                }
                IgesParameterCursor q(file_, file_.index_of(base));
                const int axis = q.pointer("axis"), gen = q.pointer("generatrix");
                const double sa = q.real("start angle");
                const double ta = whole_turn_snapped(sa, q.real("terminate angle"));
                if (axis == 0 || gen == 0) q.fail("surface of revolution without axis or generatrix");
                const geom::NurbsCurve3d line = single_curve(axis, "axis");
                const Vector3d p0 = line.evaluate(line.domain().first);
                const Vector3d a = (line.evaluate(line.domain().second) - p0).normalized();
                if (!a.allFinite()) q.fail("axis line has zero length");
                geom::NurbsCurve3d g = single_curve(gen, "generatrix");
                const NurbsSurface B = geom::surface_of_revolution(g, p0, a, sa, ta);
                const double t0 = g.domain().first;
                const auto dg = g.derivatives(t0, 1);
                Vector3d r = dg[0] - p0 - (dg[0] - p0).dot(a) * a;
                if (r.norm() < 1e-12 * (1 + dg[0].norm())) {
                    const Vector3d e = g.evaluate(g.domain().second);
                    r = e - p0 - (e - p0).dot(a) * a;
                }
                const Vector3d n_g = a.cross(r).cross(dg[1]).normalized();
                const Vector3d NB = B.normal(B.domain_u().first, B.domain_v().first);
                const Vector3d rotated = Eigen::AngleAxisd(sa, a) * n_g;
                // IGES 5.3 Sec. 4.39: S + d N with N = Su x Sv of the base in its
                // native (generatrix, angle) parameters, as our NURBS has it; the
                // indicator only documents the side (bug23171_tube_surf.igs
                // agrees with its model-space trims this way, not the other).
                (void)indicator;
                const double delta = (NB.dot(rotated) < 0 ? -1.0 : 1.0) * d;
                std::vector<Vector3d> P = g.points();
                if (g.degree() == 1 && P.size() == 2) {
                    for (Vector3d& x : P) x += delta * n_g;
                } else {
                    // A circular arc: centre from three of its points, all others checked.
                    const auto [g0, g1] = g.domain();
                    const Vector3d A = g.evaluate(g0), M = g.evaluate(0.5 * (g0 + g1)), C = g.evaluate(g1);
                    const Vector3d ab = M - A, ac = C - A, w = ab.cross(ac);
                    if (w.squaredNorm() <= 0) q.fail("offset of this generatrix not supported");
                    const Vector3d center = A + (w.cross(ab) * ac.squaredNorm() + ac.cross(w) * ab.squaredNorm()) /
                                                    (2 * w.squaredNorm());
                    const double rho = (A - center).norm();
                    for (int k = 0; k <= 16; ++k)
                        if (std::fabs((g.evaluate(g0 + (g1 - g0) * k / 16) - center).norm() - rho) > 1e-9 * rho)
                            q.fail("offset of a generatrix that is neither a line nor a circular arc not supported");
                    const double rho2 = rho + delta * n_g.dot((A - center) / rho);
                    if (!(rho2 > 0)) c.fail("offset distance collapses the generatrix arc");
                    for (Vector3d& x : P) x = center + (x - center) * (rho2 / rho);
                }
                g = geom::NurbsCurve3d(g.degree(), g.knots(), std::move(P),
                                       g.is_rational() ? g.weights() : std::vector<double>{});
                out.nurbs = geom::surface_of_revolution(g, p0, a, sa, ta).transformed(transform_of(base));
                out.kind = "offset";
                out.map = IgesSurface::Map::kAngleV;
                out.angle.emplace(sa, ta);
                out.angle_u = arc_angles(gen, g);
                break;
            }
            default:
                c.fail("entity " + std::to_string(e.type) + " is not a surface");
        }
    } catch (const geom::InvalidInput& err) {
        fail(de, err.what());
    } catch (const geom::NumericalFailure& err) {
        fail(de, err.what());
    }
    if (e.transform != 0) out.nurbs = out.nurbs.transformed(own);
    if (out.map == IgesSurface::Map::kAngleV)
        out.periodic_angle = geom::is_closed_surface(out.nurbs, 1, closure_tolerance(out.nurbs));
    return out;
}

double IgesReader::closure_tolerance(const geom::NurbsSurface& s) const {
    return io::closure_tolerance(s, file_.global().min_resolution);
}

std::optional<geom::NurbsCurve2d> IgesReader::map_to_nurbs(const IgesSurface& s,
                                                           const geom::NurbsCurve2d& c) const {
    if (s.map == IgesSurface::Map::kNone) return std::nullopt;
    auto affine = [&](Vector2d p) {
        if (s.swap) std::swap(p.x(), p.y());
        return Vector2d(s.su * p.x() + s.ou, s.sv * p.y() + s.ov);
    };
    std::vector<Vector2d> P;
    P.reserve(c.points().size());
    const std::vector<double> w = c.is_rational() ? c.weights() : std::vector<double>{};
    if (s.map == IgesSurface::Map::kAffine && !s.angle_u) {
        for (const Vector2d& p : c.points()) P.push_back(affine(p));
        return geom::NurbsCurve2d(c.degree(), c.knots(), std::move(P), w);
    }
    // kAngleV: v = map(θ) is not affine, nor u = angle_u(θ). Axis-parallel
    // polylines map exactly point by point; other curves are sampled densely
    // into a polyline. On a closed sweep an angle λ = σ(θ - θ0) past [0, 2π) maps
    // through θ - σ 2π k, k = floor(λ / 2π), onto v + k T (T the NURBS period,
    // |θ1 - θ0|): continuous across the seam (exactly when the sweep is 2π).
    auto periodic = [](const geom::ArcParameterMap& m, double theta) {
        const double sigma = m.direction(), sweep = std::fabs(m.theta1() - m.theta0());
        const double k = std::floor(sigma * (theta - m.theta0()) / (2 * kPi));
        return m.to_nurbs(theta - sigma * 2 * kPi * k) + k * sweep;
    };
    // An open arc: the turn of θ nearest the arc's middle (see IgesSurface::angle_u).
    auto nearest_turn = [](const geom::ArcParameterMap& m, double theta) {
        const double middle = 0.5 * (m.theta0() + m.theta1());
        return m.to_nurbs(theta - 2 * kPi * std::round((theta - middle) / (2 * kPi)));
    };
    const bool closed_u =
        s.angle_u && std::fabs(s.angle_u->theta1() - s.angle_u->theta0()) >= 2 * kPi - geom::kAngleSlack;
    auto mapped = [&](Vector2d p) {
        p = affine(p);
        if (s.angle_u) p.x() = closed_u ? periodic(*s.angle_u, p.x()) : nearest_turn(*s.angle_u, p.x());
        if (s.map == IgesSurface::Map::kAngleV)
            p.y() = s.periodic_angle ? periodic(*s.angle, p.y()) : s.angle->to_nurbs(p.y());
        return p;
    };
    bool axis_parallel = c.degree() == 1;
    for (std::size_t i = 1; axis_parallel && i < c.points().size(); ++i) {
        const Vector2d d = c.points()[i] - c.points()[i - 1];
        const double tol = 1e-12 * (1 + c.points()[i].cwiseAbs().maxCoeff());
        axis_parallel = std::fabs(d.x()) <= tol || std::fabs(d.y()) <= tol;
    }
    if (axis_parallel) {
        for (const Vector2d& p : c.points()) P.push_back(mapped(p));
        return geom::NurbsCurve2d(1, c.knots(), std::move(P));
    }
    const auto [a, b] = c.domain();
    std::vector<double> breaks;
    for (double u : c.knots())
        if (u >= a && u <= b && (breaks.empty() || u > breaks.back())) breaks.push_back(u);
    constexpr int kPerSpan = 16;
    std::vector<double> t;
    for (std::size_t k = 0; k + 1 < breaks.size(); ++k)
        for (int j = 0; j < kPerSpan; ++j) t.push_back(breaks[k] + (breaks[k + 1] - breaks[k]) * j / kPerSpan);
    t.push_back(b);
    for (double x : t) P.push_back(mapped(c.evaluate(x)));
    std::vector<double> U{t.front()};
    U.insert(U.end(), t.begin(), t.end());
    U.push_back(t.back());
    return geom::NurbsCurve2d(1, std::move(U), std::move(P));
}

}  // namespace trimkit::io
