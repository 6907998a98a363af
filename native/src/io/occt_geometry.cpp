#include "io/occt_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include <Geom2dConvert.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Geom2d_TrimmedCurve.hxx>
#include <GeomConvert.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_BezierCurve.hxx>
#include <Geom_BezierSurface.hxx>
#include <Geom_Circle.hxx>
#include <Geom_ConicalSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Ellipse.hxx>
#include <Geom_Line.hxx>
#include <Geom_OffsetSurface.hxx>
#include <Geom_Plane.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_SurfaceOfLinearExtrusion.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <Precision.hxx>
#include <gp_Ax3.hxx>

#include "geom/analytic_curves.h"
#include "geom/analytic_surfaces.h"
#include "geom/error.h"
#include "geom/extend_closed_surface.h"
#include "geom/extrapolate_surface.h"
#include "io/occt_support.h"

namespace trimkit::io {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

constexpr double kTwoPi = 2.0 * M_PI;
// Linear parameter ranges of unbounded surfaces are widened by this share of their
// extent (and at least this much absolutely) so trims on the box's edge stay inside.
constexpr double kLinearPadShare = 1e-3;
// B-spline surfaces are continued past their domain for trims that run outside it by
// at most this share of the domain's length (real files stray by far less; more is
// a broken file, whose trims are then clamped to the domain).
constexpr double kMaxExtensionShare = 0.25;
// Angle ranges are widened by at most this (radians), never beyond one period.
constexpr double kAnglePad = 1e-9;
// A wound surface's boundary rows one turn apart coincide within this share of its size.
constexpr double kClosureShare = 1e-9;

Vector2d to_vec(const gp_Pnt2d& p) { return {p.X(), p.Y()}; }
Vector3d to_vec(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
Vector3d to_vec(const gp_Dir& d) { return {d.X(), d.Y(), d.Z()}; }

// The map from the local frame (e1, e2, e3 at 0) to the placement's (X, Y, Z at O);
// Y is the placement's own, so left-handed frames come out right too.
Eigen::Affine3d frame_of(const gp_Ax3& ax) {
    Eigen::Affine3d M = Eigen::Affine3d::Identity();
    M.linear().col(0) = to_vec(ax.XDirection());
    M.linear().col(1) = to_vec(ax.YDirection());
    M.linear().col(2) = to_vec(ax.Direction());
    M.translation() = to_vec(ax.Location());
    return M;
}

std::pair<double, double> linear_range(double lo, double hi) {
    const double pad = kLinearPadShare * std::max(1.0, hi - lo);
    return {lo - pad, hi + pad};
}

// Sweeps within this of a whole turn are one turn (rounding of 2π in files and bounds).
constexpr double kTurnSlack = 1e-9;

// [lo, hi] widened by kAnglePad (not past a whole turn) and within [floor, ceil]; a
// sweep past one turn by more than kTurnSlack is kept (a wound face, see wind()).
std::pair<double, double> angle_range(double lo, double hi, double floor = -1e300, double ceil = 1e300) {
    if (hi - lo > kTwoPi && hi - lo <= kTwoPi + kTurnSlack) hi = lo + kTwoPi;
    const double pad = hi - lo < kTwoPi ? std::min(kAnglePad, 0.5 * (kTwoPi - (hi - lo))) : 0.0;
    return {std::max(floor, lo - pad), std::min(ceil, hi + pad)};
}

// The end of the first turn of [a, b].
double one_turn(double a, double b) { return std::min(b, a + kTwoPi); }

// A surface built over one turn [a, a + 2π] of `direction` wound on to b (its copies
// joined, extend_closed_surface), and its axis map told the period.
void wind(TranslatedSurface& out, int direction, double a, double b) {
    if (b <= a + kTwoPi) return;
    const Eigen::AlignedBox3d box = out.nurbs.control_box();
    out.nurbs = geom::extend_closed_surface(out.nurbs, direction, a, b, kClosureShare * box.diagonal().norm());
    (direction == 0 ? out.map.u : out.map.v).period = kTwoPi;
}

geom::AxisMap arc_axis(double theta0, double theta1) {
    geom::AxisMap a;
    a.arc.emplace(theta0, theta1);
    return a;
}

template <int Dim, class BSpline>
geom::NurbsCurve<Dim> nurbs_of(const BSpline& b) {
    std::vector<Eigen::Matrix<double, Dim, 1>> P;
    std::vector<double> w;
    for (int i = 1; i <= b->NbPoles(); ++i) {
        P.push_back(to_vec(b->Pole(i)));
        if (b->IsRational()) w.push_back(b->Weight(i));
    }
    return geom::NurbsCurve<Dim>(b->Degree(),
                                 expanded_knots(b->NbKnots(), [&](int i) { return b->Knot(i); },
                                                [&](int i) { return b->Multiplicity(i); }),
                                 std::move(P), std::move(w));
}

// Restricts `c` to [a, b] unless that is (to rounding) its whole domain; a range
// reaching outside the domain keeps the whole curve.
template <int Dim>
geom::NurbsCurve<Dim> restricted(const geom::NurbsCurve<Dim>& c, double a, double b) {
    const auto [lo, hi] = c.domain();
    const double tol = 1e-9 * std::max(1.0, hi - lo);
    if (a < lo - tol || b > hi + tol) return c;
    if (std::abs(a - lo) <= tol && std::abs(b - hi) <= tol) return c;
    return c.sub_curve(std::max(a, lo), std::min(b, hi));
}

// A periodic B-spline over [first, last] within one period: the period unrolled
// (SetNotPeriodic keeps the parameterisation over [FirstParameter, + period]) and
// cut to the range shifted by whole periods, knots shifted back. Empty when the
// range runs across the period's end. (OCCT's CurveToBSplineCurve of a trimmed
// periodic B-spline over exactly one period returns a curve that does not close:
// the plane faces of a .brep prism over a periodic outline.)
template <int Dim, class Handle>
std::optional<geom::NurbsCurve<Dim>> unrolled_period(const Handle& b, double first, double last) {
    const double period = b->Period(), f0 = b->FirstParameter(), eps = 1e-9 * period;
    const double k = std::floor((first - f0 + eps) / period);
    const double a = first - k * period, c = last - k * period;
    if (!(period > 0.0) || c > f0 + period + eps) return std::nullopt;
    Handle copy = Handle::DownCast(b->Copy());
    copy->SetNotPeriodic();
    const geom::NurbsCurve<Dim> n = restricted(nurbs_of<Dim>(copy), a, std::min(c, f0 + period));
    if (k == 0.0) return n;
    std::vector<double> knots = n.knots();
    for (double& t : knots) t += k * period;
    return geom::NurbsCurve<Dim>(n.degree(), std::move(knots), n.points(),
                                 n.is_rational() ? n.weights() : std::vector<double>{});
}

// A 3D curve over [first, last] with the map from its OCCT parameter to the NURBS
// one: identity for lines and B-splines, the arc map for circles and ellipses.
struct MappedCurve {
    geom::NurbsCurve3d curve;
    geom::AxisMap map;
};

MappedCurve mapped_curve(Handle(Geom_Curve) c, double first, double last) {
    while (auto t = Handle(Geom_TrimmedCurve)::DownCast(c)) c = t->BasisCurve();
    if (auto line = Handle(Geom_Line)::DownCast(c))
        return {geom::line_segment(to_vec(line->Value(first)), to_vec(line->Value(last)), first, last), {}};
    if (auto circle = Handle(Geom_Circle)::DownCast(c)) {
        const gp_Ax2& ax = circle->Position();
        const auto [a, b0] = angle_range(first, last);
        const double b = one_turn(a, b0);
        return {geom::circular_arc(to_vec(ax.Location()), to_vec(ax.XDirection()), to_vec(ax.YDirection()),
                                   circle->Radius(), a, b),
                arc_axis(a, b)};
    }
    if (auto ellipse = Handle(Geom_Ellipse)::DownCast(c)) {
        const gp_Ax2& ax = ellipse->Position();
        const auto [a, b0] = angle_range(first, last);
        const double b = one_turn(a, b0);
        return {geom::ellipse_arc(to_vec(ax.Location()), to_vec(ax.XDirection()), to_vec(ax.YDirection()),
                                  ellipse->MajorRadius(), ellipse->MinorRadius(), a, b),
                arc_axis(a, b)};
    }
    if (auto bezier = Handle(Geom_BezierCurve)::DownCast(c))
        return {restricted(nurbs_of<3>(GeomConvert::CurveToBSplineCurve(bezier)), first, last), {}};
    if (auto bspline = Handle(Geom_BSplineCurve)::DownCast(c); bspline && !bspline->IsPeriodic())
        return {restricted(nurbs_of<3>(bspline), first, last), {}};
    if (auto bspline = Handle(Geom_BSplineCurve)::DownCast(c)) {
        if (auto one = unrolled_period<3>(bspline, first, last)) return {*one, {}};
        return {nurbs_of<3>(GeomConvert::CurveToBSplineCurve(new Geom_TrimmedCurve(bspline, first, last))), {}};
    }
    throw UntranslatedKind(std::string("curve kind ") + c->DynamicType()->Name());
}

geom::NurbsSurface bspline_surface(Handle(Geom_BSplineSurface) s, const Eigen::AlignedBox2d& range) {
    s = Handle(Geom_BSplineSurface)::DownCast(s->Copy());
    double u0 = 0, u1 = 0, v0 = 0, v1 = 0;
    s->Bounds(u0, u1, v0, v1);
    // A periodic surface whose trims leave its first period is cut to the trims' range
    // (Geom_BSplineSurface::Segment accepts ranges across the period).
    const double tol_u = 1e-9 * (u1 - u0), tol_v = 1e-9 * (v1 - v0);
    const bool out_u = s->IsUPeriodic() && (range.min().x() < u0 - tol_u || range.max().x() > u1 + tol_u);
    const bool out_v = s->IsVPeriodic() && (range.min().y() < v0 - tol_v || range.max().y() > v1 + tol_v);
    if (out_u || out_v) {
        const double a = out_u ? range.min().x() : u0, b = out_u ? std::min(range.max().x(), a + s->UPeriod()) : u1;
        const double c = out_v ? range.min().y() : v0, d = out_v ? std::min(range.max().y(), c + s->VPeriod()) : v1;
        s->Segment(a, b, c, d);
    }
    const bool periodic_u = s->IsUPeriodic(), periodic_v = s->IsVPeriodic();
    if (periodic_u) s->SetUNotPeriodic();
    if (periodic_v) s->SetVNotPeriodic();
    const int nu = s->NbUPoles(), nv = s->NbVPoles();
    const bool rational = s->IsURational() || s->IsVRational();
    std::vector<Vector3d> P;
    std::vector<double> w;
    P.reserve(static_cast<size_t>(nu) * nv);
    for (int i = 1; i <= nu; ++i)
        for (int j = 1; j <= nv; ++j) {
            P.push_back(to_vec(s->Pole(i, j)));
            if (rational) w.push_back(s->Weight(i, j));
        }
    geom::NurbsSurface out(
        s->UDegree(), s->VDegree(),
        expanded_knots(s->NbUKnots(), [&](int i) { return s->UKnot(i); }, [&](int i) { return s->UMultiplicity(i); }),
        expanded_knots(s->NbVKnots(), [&](int i) { return s->VKnot(i); }, [&](int i) { return s->VMultiplicity(i); }),
        nu, nv, std::move(P), std::move(w));
    // Trims past a bounded direction's ends: the surface continues there as OCCT
    // evaluates it (extrapolate_surface.h), up to kMaxExtensionShare of the domain.
    const auto [du0, du1] = out.domain_u();
    const auto [dv0, dv1] = out.domain_v();
    auto widened = [](double lo, double hi, double want_lo, double want_hi, bool periodic) {
        const double reach = kMaxExtensionShare * (hi - lo), slack = 1e-9 * (hi - lo);
        if (periodic) return std::pair{lo, hi};
        return std::pair{want_lo < lo - slack ? std::max(want_lo, lo - reach) : lo,
                         want_hi > hi + slack ? std::min(want_hi, hi + reach) : hi};
    };
    const auto [eu0, eu1] = widened(du0, du1, range.min().x(), range.max().x(), periodic_u || out_u);
    const auto [ev0, ev1] = widened(dv0, dv1, range.min().y(), range.max().y(), periodic_v || out_v);
    if (eu0 != du0 || eu1 != du1 || ev0 != dv0 || ev1 != dv1) {
        try {
            return geom::extrapolated_surface(out, eu0, eu1, ev0, ev1);
        } catch (const geom::NumericalFailure&) {
            // A rational end span that cannot go on: the trims are clamped to the domain.
        }
    }
    return out;
}

TranslatedSurface elementary(const Handle(Geom_Surface)& s, const Eigen::AlignedBox2d& range) {
    const Vector3d O = Vector3d::Zero(), Z = Vector3d::UnitZ(), X = Vector3d::UnitX();
    const double s0 = range.min().x(), s1 = range.max().x(), t0 = range.min().y(), t1 = range.max().y();
    TranslatedSurface out;
    if (auto plane = Handle(Geom_Plane)::DownCast(s)) {
        const gp_Ax3& ax = plane->Position();
        const auto [u0, u1] = linear_range(s0, s1);
        const auto [v0, v1] = linear_range(t0, t1);
        out.nurbs = geom::plane_patch(to_vec(ax.Location()), to_vec(ax.XDirection()), to_vec(ax.YDirection()),
                                      u0, u1, v0, v1);
        out.kind = "plane";
        return out;
    }
    if (auto cyl = Handle(Geom_CylindricalSurface)::DownCast(s)) {
        const auto [a, b] = angle_range(s0, s1);
        const auto [z0, z1] = linear_range(t0, t1);
        out.nurbs = geom::cylinder_patch(O, Z, X, cyl->Radius(), a, one_turn(a, b), z0, z1)
                        .transformed(frame_of(cyl->Position()));
        out.kind = "cylinder";
        out.map.u = arc_axis(a, one_turn(a, b));
        wind(out, 0, a, b);
        return out;
    }
    if (auto cone = Handle(Geom_ConicalSurface)::DownCast(s)) {
        // OCCT's v runs along the ruling; cone_patch's along the axis: w = v cos α.
        const double alpha = cone->SemiAngle(), c = std::cos(alpha);
        const auto [a, b] = angle_range(s0, s1);
        auto [v0, v1] = linear_range(t0, t1);
        // Not past the apex (radius R + v sin α = 0) where the face reaches it (within the
        // pad, which also takes the trims' bounding box's rounding): the padded
        // range through it gave cells on both nappes, whose exact bound (revolution_error)
        // does not hold across the axis, and the generic one split a cone with its apex into
        // 2048 columns at 0.002 of its size (cone_with_apex.stp: 7035 triangles, OCCT 1089).
        const double apex = -cone->RefRadius() / std::sin(alpha), pad = t0 - v0;
        if (apex > v0 && apex <= t0 + pad) v0 = apex;
        if (apex < v1 && apex >= t1 - pad) v1 = apex;
        out.nurbs = geom::cone_patch(O, Z, X, cone->RefRadius(), alpha, a, one_turn(a, b), v0 * c, v1 * c)
                        .transformed(frame_of(cone->Position()));
        out.kind = "cone";
        out.map.u = arc_axis(a, one_turn(a, b));
        out.map.v.scale = c;
        wind(out, 0, a, b);
        return out;
    }
    if (auto sphere = Handle(Geom_SphericalSurface)::DownCast(s)) {
        const auto [a, b] = angle_range(s0, s1);
        const auto [c, d] = angle_range(t0, t1, -0.5 * M_PI, 0.5 * M_PI);
        out.nurbs = geom::sphere_patch(O, Z, X, sphere->Radius(), a, one_turn(a, b), c, d)
                        .transformed(frame_of(sphere->Position()));
        out.kind = "sphere";
        out.map.u = arc_axis(a, one_turn(a, b));
        out.map.v = arc_axis(c, d);
        wind(out, 0, a, b);
        return out;
    }
    if (auto torus = Handle(Geom_ToroidalSurface)::DownCast(s)) {
        const auto [a, b] = angle_range(s0, s1);
        const auto [c, d] = angle_range(t0, t1);
        out.nurbs = geom::torus_patch(O, Z, X, torus->MajorRadius(), torus->MinorRadius(), a, one_turn(a, b), c,
                                      one_turn(c, d))
                        .transformed(frame_of(torus->Position()));
        out.kind = "torus";
        out.map.u = arc_axis(a, one_turn(a, b));
        out.map.v = arc_axis(c, one_turn(c, d));
        wind(out, 0, a, b);
        wind(out, 1, c, d);
        return out;
    }
    throw UntranslatedKind(std::string("surface kind ") + s->DynamicType()->Name());
}

// The curve's range clamped to its own domain where it is bounded.
std::pair<double, double> curve_range(const Handle(Geom_Curve)& c, double lo, double hi) {
    if (c->IsPeriodic()) return {lo, hi};
    const double f = c->FirstParameter(), l = c->LastParameter();
    if (Precision::IsInfinite(f) || Precision::IsInfinite(l)) return linear_range(lo, hi);
    return {std::max(lo, f), std::min(hi, l)};
}

TranslatedSurface swept(const Handle(Geom_Surface)& s, const Eigen::AlignedBox2d& range) {
    const double s0 = range.min().x(), s1 = range.max().x(), t0 = range.min().y(), t1 = range.max().y();
    TranslatedSurface out;
    if (auto rev = Handle(Geom_SurfaceOfRevolution)::DownCast(s)) {
        // OCCT: u the angle, v the basis curve's parameter; ours the other way round.
        const auto [v0, v1] = curve_range(rev->BasisCurve(), t0, t1);
        const MappedCurve g = mapped_curve(rev->BasisCurve(), v0, v1);
        const auto [a, b] = angle_range(s0, s1);
        const gp_Ax1 axis = rev->Axis();
        out.nurbs = geom::surface_of_revolution(g.curve, to_vec(axis.Location()), to_vec(axis.Direction()), a,
                                                one_turn(a, b));
        out.kind = "revolution";
        out.map.swap = true;
        out.map.u = g.map;
        out.map.v = arc_axis(a, one_turn(a, b));
        wind(out, 1, a, b);
        return out;
    }
    if (auto ext = Handle(Geom_SurfaceOfLinearExtrusion)::DownCast(s)) {
        const auto [u0, u1] = curve_range(ext->BasisCurve(), s0, s1);
        const MappedCurve g = mapped_curve(ext->BasisCurve(), u0, u1);
        const auto [v0, v1] = linear_range(t0, t1);
        out.nurbs = geom::tabulated_cylinder(g.curve, to_vec(ext->Direction()), v0, v1);
        out.kind = "extrusion";
        out.map.u = g.map;
        return out;
    }
    throw UntranslatedKind(std::string("surface kind ") + s->DynamicType()->Name());
}

}  // namespace

std::string surface_kind_name(const Handle(Geom_Surface)& s) {
    if (s.IsNull()) return "unknown";
    Handle(Geom_Surface) basis = s;
    while (auto t = Handle(Geom_RectangularTrimmedSurface)::DownCast(basis)) basis = t->BasisSurface();
    if (basis->IsKind(STANDARD_TYPE(Geom_Plane))) return "plane";
    if (basis->IsKind(STANDARD_TYPE(Geom_CylindricalSurface))) return "cylinder";
    if (basis->IsKind(STANDARD_TYPE(Geom_ConicalSurface))) return "cone";
    if (basis->IsKind(STANDARD_TYPE(Geom_SphericalSurface))) return "sphere";
    if (basis->IsKind(STANDARD_TYPE(Geom_ToroidalSurface))) return "torus";
    if (basis->IsKind(STANDARD_TYPE(Geom_SurfaceOfRevolution))) return "revolution";
    if (basis->IsKind(STANDARD_TYPE(Geom_SurfaceOfLinearExtrusion))) return "extrusion";
    if (basis->IsKind(STANDARD_TYPE(Geom_BezierSurface))) return "bezier";
    if (basis->IsKind(STANDARD_TYPE(Geom_BSplineSurface))) return "bspline";
    if (basis->IsKind(STANDARD_TYPE(Geom_OffsetSurface))) return "offset";
    return "other";
}

TranslatedSurface translate_surface(const Handle(Geom_Surface)& surface, const Eigen::AlignedBox2d& range) {
    if (surface.IsNull()) throw UntranslatedKind("no surface");
    Handle(Geom_Surface) s = surface;
    while (auto t = Handle(Geom_RectangularTrimmedSurface)::DownCast(s)) s = t->BasisSurface();
    if (auto offset = Handle(Geom_OffsetSurface)::DownCast(s)) {
        // An offset of an elementary surface is elementary (OCCT finds it); others are not translated.
        const Handle(Geom_Surface) equivalent = offset->Surface();
        if (equivalent.IsNull()) throw UntranslatedKind("offset surface");
        TranslatedSurface out = translate_surface(equivalent, range);
        out.kind = "offset";
        return out;
    }
    if (s->IsKind(STANDARD_TYPE(Geom_ElementarySurface))) return elementary(s, range);
    if (s->IsKind(STANDARD_TYPE(Geom_SweptSurface))) return swept(s, range);
    TranslatedSurface out;
    if (auto bezier = Handle(Geom_BezierSurface)::DownCast(s)) {
        out.nurbs = bspline_surface(GeomConvert::SurfaceToBSplineSurface(bezier), range);
        out.kind = "bezier";
        return out;
    }
    if (auto bspline = Handle(Geom_BSplineSurface)::DownCast(s)) {
        out.nurbs = bspline_surface(bspline, range);
        out.kind = "bspline";
        return out;
    }
    throw UntranslatedKind(std::string("surface kind ") + s->DynamicType()->Name());
}

geom::NurbsCurve2d translate_curve(const Handle(Geom2d_Curve)& c, double first, double last) {
    Handle(Geom2d_BSplineCurve) b = Handle(Geom2d_BSplineCurve)::DownCast(c);
    if (!b.IsNull() && !b->IsPeriodic()) return restricted(nurbs_of<2>(b), first, last);
    if (!b.IsNull())
        if (auto one = unrolled_period<2>(b, first, last)) return *one;
    return nurbs_of<2>(Geom2dConvert::CurveToBSplineCurve(new Geom2d_TrimmedCurve(c, first, last)));
}

geom::NurbsCurve3d translate_curve(const Handle(Geom_Curve)& c, double first, double last) {
    try {
        return mapped_curve(c, first, last).curve;
    } catch (const UntranslatedKind&) {
        return nurbs_of<3>(GeomConvert::CurveToBSplineCurve(new Geom_TrimmedCurve(c, first, last)));
    }
}

}  // namespace trimkit::io
