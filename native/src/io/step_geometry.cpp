#include "io/step_geometry.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <utility>

#include "geom/analytic_curves.h"
#include "geom/analytic_surfaces.h"
#include "geom/bspline_basis.h"
#include "geom/error.h"
#include "geom/knot_vector.h"
#include "io/boundary_extent.h"

namespace trimkit::io {
namespace {

// The instance's type for messages: its record's, or "(A B ...)" for a complex one.
std::string type_of(const StepInstance& inst) {
    if (inst.records.size() == 1) return inst.records[0].type;
    std::string t = "(";
    for (const StepRecord& r : inst.records) t += (t.size() > 1 ? " " : "") + r.type;
    return t + ")";
}

// Periodic directions are built over the whole turn [0, 2pi], whatever arc the
// boundary's points cover (`covered.full` keeps whether they go all the way round):
// the points cannot tell which side of them the face lies (a ball whose loop is its
// seam edge and a hole covers a narrow arc of longitude, its face all the rest).
// face_loops unwraps loops across the seam and extends the surface over them.
AngularExtent whole_turn(const AngularExtent& covered) {
    AngularExtent turn;
    turn.lo = 0.0;
    turn.hi = 2.0 * 3.14159265358979323846;
    turn.full = covered.full;
    return turn;
}

using Eigen::Vector2d;
using Eigen::Vector3d;
using geom::NurbsCurve2d;
using geom::NurbsCurve3d;
using geom::NurbsSurface;
using EdgeRange = StepGeometry::EdgeRange;
using Surface = StepGeometry::Surface;

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2 * kPi;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// A boundary going all the way round a cone whose heights spread less than this share
// of the cone's size lies on one parallel: the face is the cap up to the apex. Files
// print coordinates with 10 to 17 digits; a real frustum is far taller.
constexpr double kOneHeightShare = 1e-7;
// Points nearer an axis than this share of the surface's size have no angle about it.
constexpr double kOnAxisShare = 1e-9;
// Samples per knot span (B-splines) or per turn (conics) before refining a nearest
// parameter: enough to land in the right basin for the curves CAD files carry.
constexpr int kSamplesPerSpan = 8;
constexpr int kSamplesPerTurn = 64;
constexpr int kMaxSamples = 4096;
// Newton steps on the nearest-point condition, and golden-section steps for the
// distances without a derivative (0.618^60 ≈ 3e-13 of the bracket).
constexpr int kNewtonSteps = 30;
constexpr int kGoldenSteps = 60;
// An edge's parameter range may pass a bounded PCURVE's domain by this share of it
// (the 3D and 2D curves' ends, rounded separately by the writer); it is clamped.
constexpr double kPcurveRangeSlack = 1e-6;
// A shift by whole turns leaves angles this share of a turn below the arc's start
// where they are (file rounding, not another turn).
constexpr double kTurnSlack = 1e-9;

// ---- Entity parameters --------------------------------------------------------------

// The attribute values of one entity (a simple record without its name, or the
// partial records of a complex instance in schema order), read with checks whose
// errors name the instance, its line and `type`.
class Params {
public:
    Params(const StepPart21& file, const StepInstance& inst, std::string type,
           std::vector<const StepValue*> values)
        : file_(&file), inst_(&inst), type_(std::move(type)), values_(std::move(values)) {}

    const StepInstance& instance() const { return *inst_; }
    const std::string& type() const { return type_; }
    std::size_t size() const { return values_.size(); }

    [[noreturn]] void fail(const std::string& reason) const {
        throw geom::ReadError(file_->name(), inst_->line,
                              "#" + std::to_string(inst_->id) + " " + type_ + ": " + reason);
    }
    const StepValue& at(std::size_t i) const { return *values_.at(i); }
    bool unset(std::size_t i) const { return at(i).kind == StepValue::Kind::kUnset; }

    static double number(const StepValue& v, bool* ok) {
        const StepValue* x = &v;
        if (x->kind == StepValue::Kind::kTyped && x->items.size() == 1) x = &x->items[0];
        *ok = x->kind == StepValue::Kind::kReal || x->kind == StepValue::Kind::kInteger;
        return x->real;
    }
    double real(std::size_t i, const char* what) const { return real_of(at(i), what); }
    double real_of(const StepValue& v, const char* what) const {
        bool ok = false;
        const double x = number(v, &ok);
        if (!ok) fail(std::string(what) + " is not a number");
        if (!std::isfinite(x)) fail(std::string(what) + " is not finite");
        return x;
    }
    long long integer_of(const StepValue& v, const char* what) const {
        if (v.kind != StepValue::Kind::kInteger) fail(std::string(what) + " is not an integer");
        return v.integer;
    }
    long long integer(std::size_t i, const char* what) const { return integer_of(at(i), what); }
    long long reference_of(const StepValue& v, const char* what) const {
        if (v.kind != StepValue::Kind::kReference) fail(std::string(what) + " is not a reference");
        return v.integer;
    }
    long long reference(std::size_t i, const char* what) const { return reference_of(at(i), what); }
    const std::vector<StepValue>& list_of(const StepValue& v, const char* what) const {
        if (v.kind != StepValue::Kind::kList) fail(std::string(what) + " is not a list");
        return v.items;
    }
    const std::vector<StepValue>& list(std::size_t i, const char* what) const { return list_of(at(i), what); }
    bool boolean(std::size_t i, const char* what) const {
        const StepValue& v = at(i);
        if (v.kind == StepValue::Kind::kEnum && (v.text == "T" || v.text == "F")) return v.text == "T";
        fail(std::string(what) + " is not .T. or .F.");
    }

private:
    const StepPart21* file_;
    const StepInstance* inst_;
    std::string type_;
    std::vector<const StepValue*> values_;
};

// ---- Native curves --------------------------------------------------------------------

// A STEP curve in its own parameter: lines and conics analytically (unbounded or
// periodic, sized by the caller), everything bounded as its NURBS.
struct Curve {
    enum class Kind { kLine, kCircle, kEllipse, kBounded };
    Kind kind = Kind::kBounded;
    Vector3d O = Vector3d::Zero();  // line: a point; conics: the centre
    Vector3d X = Vector3d::UnitX();  // line: the direction times magnitude; conics: unit axis
    Vector3d Y = Vector3d::UnitY();  // conics: unit axis, Z × X
    double a = 0, b = 0;             // circle: radius a; ellipse: semi-axes a, b
    NurbsCurve3d nurbs;              // kBounded

    bool conic() const { return kind == Kind::kCircle || kind == Kind::kEllipse; }
    Vector3d at(double t) const {
        switch (kind) {
            case Kind::kLine: return O + t * X;
            case Kind::kCircle: return O + a * (std::cos(t) * X + std::sin(t) * Y);
            case Kind::kEllipse: return O + a * std::cos(t) * X + b * std::sin(t) * Y;
            case Kind::kBounded: break;
        }
        return nurbs.evaluate(t);
    }
    // A scale of the curve's size, for relative tests.
    double size() const {
        if (kind == Kind::kBounded) return nurbs.control_box().diagonal().norm() + nurbs.control_box().max().norm();
        return O.norm() + a + b + X.norm();
    }
    // Parameters to sample before refining a nearest point.
    std::vector<double> grid() const {
        std::vector<double> t;
        if (conic()) {
            for (int k = 0; k <= kSamplesPerTurn; ++k) t.push_back(-kPi + kTwoPi * k / kSamplesPerTurn);
            return t;
        }
        const std::vector<double> breaks = geom::distinct_knots(nurbs.knots(), nurbs.degree());
        const int per = std::max(1, std::min(kSamplesPerSpan, kMaxSamples / static_cast<int>(breaks.size())));
        for (std::size_t k = 0; k + 1 < breaks.size(); ++k)
            for (int j = 0; j < per; ++j) t.push_back(breaks[k] + (breaks[k + 1] - breaks[k]) * j / per);
        t.push_back(breaks.back());
        return t;
    }
};

// The t of `grid` minimising f, refined by golden sections within its neighbours.
template <class F>
double minimise(const std::vector<double>& grid, const F& f) {
    std::size_t best = 0;
    double fb = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < grid.size(); ++k) {
        const double v = f(grid[k]);
        if (v < fb) {
            fb = v;
            best = k;
        }
    }
    double lo = grid[best > 0 ? best - 1 : best], hi = grid[best + 1 < grid.size() ? best + 1 : best];
    const double g = 0.5 * (std::sqrt(5.0) - 1);
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = f(x1), f2 = f(x2);
    for (int k = 0; k < kGoldenSteps && hi > lo; ++k) {
        if (f1 < f2) {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - g * (hi - lo);
            f1 = f(x1);
        } else {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + g * (hi - lo);
            f2 = f(x2);
        }
    }
    const double t = 0.5 * (lo + hi);
    return f(t) <= fb ? t : grid[best];
}

// The parameter of the curve's point nearest p (conics: an angle in about [-π, π]).
double nearest_parameter(const Curve& c, const Vector3d& p) {
    switch (c.kind) {
        case Curve::Kind::kLine: return (p - c.O).dot(c.X) / c.X.squaredNorm();
        case Curve::Kind::kCircle: return std::atan2((p - c.O).dot(c.Y), (p - c.O).dot(c.X));
        case Curve::Kind::kEllipse: {
            // Newton on (E(θ) - p)·E'(θ) = 0 from the eccentric angle of p's projection.
            const double x = (p - c.O).dot(c.X), y = (p - c.O).dot(c.Y);
            double t = std::atan2(y / c.b, x / c.a);
            for (int k = 0; k < kNewtonSteps; ++k) {
                const double s = std::sin(t), co = std::cos(t);
                const double ex = c.a * co - x, ey = c.b * s - y;  // E - p in (X, Y)
                const double dx = -c.a * s, dy = c.b * co, ddx = -c.a * co, ddy = -c.b * s;
                const double f1 = ex * dx + ey * dy, f2 = dx * dx + dy * dy + ex * ddx + ey * ddy;
                if (!(f2 > 0)) break;
                const double step = f1 / f2;
                t -= std::max(-0.5, std::min(0.5, step));
                if (std::fabs(step) < 1e-15) break;
            }
            return t;
        }
        case Curve::Kind::kBounded: break;
    }
    const NurbsCurve3d& n = c.nurbs;
    const std::vector<double> grid = c.grid();
    double t = grid.front(), best = std::numeric_limits<double>::infinity();
    std::size_t k_best = 0;
    for (std::size_t k = 0; k < grid.size(); ++k) {
        const double d = (n.evaluate(grid[k]) - p).squaredNorm();
        if (d < best) {
            best = d;
            t = grid[k];
            k_best = k;
        }
    }
    // Newton on (C(t) - p)·C'(t) = 0 within the samples around the best one.
    const double lo = grid[k_best > 0 ? k_best - 1 : 0], hi = grid[std::min(k_best + 1, grid.size() - 1)];
    double x = t;
    for (int k = 0; k < kNewtonSteps; ++k) {
        const std::vector<Vector3d> d = n.derivatives(x, 2);
        const double f1 = (d[0] - p).dot(d[1]), f2 = d[1].squaredNorm() + (d[0] - p).dot(d[2]);
        if (!(f2 > 0)) break;
        const double next = std::max(lo, std::min(hi, x - f1 / f2));
        const bool done = std::fabs(next - x) <= 1e-15 * (1 + std::fabs(x));
        x = next;
        if (done) break;
    }
    return (n.evaluate(x) - p).squaredNorm() <= best ? x : t;
}

// c1 followed by c2 (c2 starting where c1 ends, same degree, both clamped), c2's
// parameter shifted to continue c1's; c2's weights scaled to meet c1's at the join.
NurbsCurve3d joined(const NurbsCurve3d& c1, const NurbsCurve3d& c2) {
    const int p = c1.degree();
    const double shift = c1.domain().second - c2.domain().first;
    std::vector<double> U(c1.knots().begin(), c1.knots().end() - 1);
    for (std::size_t i = static_cast<std::size_t>(p) + 1; i < c2.knots().size(); ++i) U.push_back(c2.knots()[i] + shift);
    std::vector<Vector3d> P = c1.points();
    P.insert(P.end(), c2.points().begin() + 1, c2.points().end());
    std::vector<double> w;
    if (c1.is_rational() || c2.is_rational()) {
        w = c1.weights();
        const double scale = c1.weights().back() / c2.weights().front();
        for (std::size_t i = 1; i < c2.weights().size(); ++i) w.push_back(c2.weights()[i] * scale);
    }
    return NurbsCurve3d(p, std::move(U), std::move(P), std::move(w));
}

// ---- The translator -------------------------------------------------------------------

struct Frame {
    Vector3d O, X, Y, Z;
};

// A plane, cylinder, cone, sphere or torus as ISO 10303-42 defines it on its frame.
struct Elementary {
    enum class Kind { kPlane, kCylinder, kCone, kSphere, kTorus };
    Kind kind = Kind::kPlane;
    Frame f;
    double r = 0;      // radius; cone: at the location; torus: major
    double minor = 0;  // torus
    double alpha = 0;  // cone: semi-angle (radians)
    int part = 0;      // degenerate torus: +1 outer (select_outer), -1 inner; 0 ordinary
};

const char* const kSimpleBSplineCurves[] = {"B_SPLINE_CURVE_WITH_KNOTS", "BEZIER_CURVE", "QUASI_UNIFORM_CURVE",
                                            "UNIFORM_CURVE"};
const char* const kSimpleBSplineSurfaces[] = {"B_SPLINE_SURFACE_WITH_KNOTS", "BEZIER_SURFACE",
                                              "QUASI_UNIFORM_SURFACE", "UNIFORM_SURFACE"};

class Translator {
public:
    Translator(const StepPart21& file, double angle_factor) : file_(file), angle_factor_(angle_factor) {}

    // The instance `id` for a public entry point.
    const StepInstance& top(long long id) const {
        const StepInstance* inst = file_.find(id);
        if (!inst) throw geom::ReadError(file_.name(), 0, "#" + std::to_string(id) + " is not defined");
        return *inst;
    }
    // The main type of an instance: its record's, or the complex instance's records.
    // The parameters of a simple instance of `type` without its name, `count` of them.
    Params simple(const StepInstance& inst, std::size_t count) const {
        const StepRecord& r = inst.records.front();
        Params p(file_, inst, type_of(inst), {});
        if (inst.records.size() != 1) p.fail("complex instance where a simple " + r.type + " was expected");
        if (r.params.size() != count + 1)
            p.fail("has " + std::to_string(r.params.size()) + " parameters, expected " + std::to_string(count + 1));
        std::vector<const StepValue*> v;
        for (std::size_t i = 1; i < r.params.size(); ++i) v.push_back(&r.params[i]);
        return Params(file_, inst, r.type, std::move(v));
    }
    // The instance referred to by parameter i of p, which must be of one of `types`.
    const StepInstance& referred(const Params& p, std::size_t i, const char* what,
                                 std::initializer_list<const char*> types) const {
        const long long id = p.reference(i, what);
        const StepInstance* inst = file_.find(id);
        if (!inst) p.fail(std::string(what) + " #" + std::to_string(id) + " is not defined");
        std::string expected;
        for (const char* t : types) {
            if (inst->records.size() == 1 && inst->records[0].type == t) return *inst;
            expected += (expected.empty() ? "" : " or ") + std::string(t);
        }
        p.fail(std::string(what) + " #" + std::to_string(id) + " is a " + type_of(*inst) + ", expected " + expected);
    }
    const StepInstance& defined(const Params& p, std::size_t i, const char* what) const {
        const long long id = p.reference(i, what);
        const StepInstance* inst = file_.find(id);
        if (!inst) p.fail(std::string(what) + " #" + std::to_string(id) + " is not defined");
        return *inst;
    }
    static void check_depth(const Params& p, int depth) {
        if (depth > kMaxStepGeometryNesting)
            p.fail("references nest deeper than " + std::to_string(kMaxStepGeometryNesting) +
                   " (a reference cycle)");
    }

    // ---- points, directions, placements ----

    Vector3d point(const StepInstance& inst) const {
        const Params p = simple(inst, 1);
        if (p.type() != "CARTESIAN_POINT") p.fail("expected a CARTESIAN_POINT");
        return coordinates(p, "coordinates");
    }
    static Vector3d coordinates(const Params& p, const char* what) {
        const std::vector<StepValue>& c = p.list(0, what);
        if (c.size() != 2 && c.size() != 3)
            p.fail(std::string(what) + " has " + std::to_string(c.size()) + " values, expected 2 or 3");
        Vector3d x = Vector3d::Zero();
        for (std::size_t k = 0; k < c.size(); ++k) x[static_cast<int>(k)] = p.real_of(c[k], what);
        return x;
    }
    Vector3d direction(const StepInstance& inst) const {
        const Params p = simple(inst, 1);
        if (p.type() != "DIRECTION") p.fail("expected a DIRECTION");
        const Vector3d d = coordinates(p, "direction_ratios");
        if (!(d.norm() > 0)) p.fail("direction_ratios are zero");
        return d.normalized();
    }
    Vector3d vector(const StepInstance& inst) const {
        const Params p = simple(inst, 2);
        if (p.type() != "VECTOR") p.fail("expected a VECTOR");
        const Vector3d d = direction(referred(p, 0, "orientation", {"DIRECTION"}));
        const double m = p.real(1, "magnitude");
        if (!(m > 0)) p.fail("magnitude " + geom::format_value(m) + " must be > 0");
        return m * d;
    }
    Frame placement(const StepInstance& inst) const {
        const std::string type = type_of(inst);
        const bool three = type == "AXIS2_PLACEMENT_3D", two = type == "AXIS2_PLACEMENT_2D";
        if (!three && !two && type != "AXIS1_PLACEMENT")
            Params(file_, inst, type, {}).fail("expected an AXIS2_PLACEMENT_3D, AXIS2_PLACEMENT_2D or AXIS1_PLACEMENT");
        const Params p = simple(inst, three ? 3 : 2);
        Frame f;
        f.O = point(referred(p, 0, "location", {"CARTESIAN_POINT"}));
        f.Z = Vector3d::UnitZ();
        if (!two && !p.unset(1)) f.Z = direction(referred(p, 1, "axis", {"DIRECTION"}));
        const std::size_t ref = three ? 2 : 1;
        Vector3d v = Vector3d::Zero();
        if (type != "AXIS1_PLACEMENT" && !p.unset(ref))
            v = direction(referred(p, ref, "ref_direction", {"DIRECTION"}));
        // A ref_direction along the axis (ul_to252.step's planes: axis -x, ref +x) is
        // taken as unset, as OCCT's reader does, rather than losing the face.
        if (v.cross(f.Z).norm() <= geom::kAnalyticTolerance) {
            // ISO 10303-42 first_proj_axis without arg.
            v = f.Z.cross(Vector3d::UnitX()).norm() <= geom::kAnalyticTolerance ? Vector3d::UnitY()
                                                                                 : Vector3d::UnitX();
        }
        f.X = (v - v.dot(f.Z) * f.Z).normalized();
        f.Y = f.Z.cross(f.X);
        return f;
    }

    // ---- curves ----

    Curve curve(const StepInstance& inst, int depth) const {
        if (inst.records.size() > 1) {
            if (!inst.record("B_SPLINE_CURVE")) unsupported(inst, "complex curve");
            return bounded(bspline_curve(inst));
        }
        const std::string& type = inst.records[0].type;
        for (const char* t : kSimpleBSplineCurves)
            if (type == t) return bounded(bspline_curve(inst));
        Curve c;
        if (type == "LINE") {
            const Params p = simple(inst, 2);
            c.kind = Curve::Kind::kLine;
            c.O = point(referred(p, 0, "pnt", {"CARTESIAN_POINT"}));
            c.X = vector(referred(p, 1, "dir", {"VECTOR"}));
            return c;
        }
        if (type == "CIRCLE" || type == "ELLIPSE") {
            const bool circle = type == "CIRCLE";
            const Params p = simple(inst, circle ? 2 : 3);
            const Frame f = placement(
                referred(p, 0, "position", {"AXIS2_PLACEMENT_3D", "AXIS2_PLACEMENT_2D"}));
            c.kind = circle ? Curve::Kind::kCircle : Curve::Kind::kEllipse;
            c.O = f.O;
            c.X = f.X;
            c.Y = f.Y;
            c.a = p.real(1, circle ? "radius" : "semi_axis_1");
            c.b = circle ? c.a : p.real(2, "semi_axis_2");
            if (!(c.a > 0) || !(c.b > 0))
                p.fail(circle ? "radius " + geom::format_value(c.a) + " must be > 0"
                              : "semi-axes " + geom::format_value(c.a) + ", " + geom::format_value(c.b) +
                                    " must be > 0");
            return c;
        }
        if (type == "POLYLINE") {
            const Params p = simple(inst, 1);
            const std::vector<StepValue>& list = p.list(0, "points");
            if (list.size() < 2) p.fail("has " + std::to_string(list.size()) + " points, expected at least 2");
            std::vector<Vector3d> P;
            std::vector<double> U{0.0};
            for (std::size_t k = 0; k < list.size(); ++k) {
                const long long id = p.reference_of(list[k], "point");
                const StepInstance* q = file_.find(id);
                if (!q) p.fail("point #" + std::to_string(id) + " is not defined");
                P.push_back(point(*q));
                U.push_back(static_cast<double>(k));  // ISO 10303-42: segment i on [i-1, i]
            }
            U.push_back(static_cast<double>(list.size() - 1));
            return bounded(NurbsCurve3d(1, std::move(U), std::move(P)));
        }
        if (type == "TRIMMED_CURVE") {
            const Params p = simple(inst, 5);
            check_depth(p, depth);
            return curve(defined(p, 0, "basis_curve"), depth + 1);
        }
        if (type == "SURFACE_CURVE" || type == "SEAM_CURVE" || type == "INTERSECTION_CURVE") {
            const Params p = simple(inst, 3);
            check_depth(p, depth);
            return curve(defined(p, 0, "curve_3d"), depth + 1);
        }
        if (type == "PCURVE") unsupported(inst, "a PCURVE is not a 3D curve");
        unsupported(inst, "curve kind not translated");
    }

    [[noreturn]] void unsupported(const StepInstance& inst, const std::string& why) const {
        unsupported_step_entity(file_, inst, why);
    }

    static Curve bounded(NurbsCurve3d n) {
        Curve c;
        c.kind = Curve::Kind::kBounded;
        c.nurbs = std::move(n);
        return c;
    }

    // ---- B-splines ----

    // The values of a B-spline curve or surface: the B_SPLINE_* attributes (without
    // the name), the knot part of its subtype and the weights, from a simple instance
    // or the partial records of a complex one. `specific` is the subtype.
    struct BSplineValues {
        std::vector<const StepValue*> base, knots;
        const StepValue* weights = nullptr;
        std::string specific;
    };
    BSplineValues bspline_values(const StepInstance& inst, bool surface) const {
        const std::size_t base_count = surface ? 7 : 5, knot_count = surface ? 5 : 3;
        const char* const* kinds = surface ? kSimpleBSplineSurfaces : kSimpleBSplineCurves;
        BSplineValues v;
        auto take = [](const StepRecord& r, std::size_t first, std::vector<const StepValue*>* out) {
            for (std::size_t i = first; i < r.params.size(); ++i) out->push_back(&r.params[i]);
        };
        if (inst.records.size() == 1) {
            const StepRecord& r = inst.records[0];
            v.specific = r.type;
            const std::size_t need = 1 + base_count + (r.type == kinds[0] ? knot_count : 0);
            if (r.params.size() != need)
                Params(file_, inst, r.type, {}).fail("has " + std::to_string(r.params.size()) +
                                                     " parameters, expected " + std::to_string(need));
            for (std::size_t i = 1; i <= base_count; ++i) v.base.push_back(&r.params[i]);
            take(r, 1 + base_count, &v.knots);
            return v;
        }
        const char* base_type = surface ? "B_SPLINE_SURFACE" : "B_SPLINE_CURVE";
        const StepRecord* base = inst.record(base_type);
        for (int k = 0; k < 4 && v.specific.empty(); ++k)
            if (const StepRecord* r = inst.record(kinds[k])) {
                v.specific = kinds[k];
                take(*r, 0, &v.knots);
                const std::size_t need = k == 0 ? knot_count : 0;
                if (r->params.size() != need)
                    Params(file_, inst, kinds[k], {}).fail("has " + std::to_string(r->params.size()) +
                                                           " parameters, expected " + std::to_string(need));
            }
        const Params p(file_, inst, type_of(inst), {});
        if (!base) p.fail(std::string("complex instance without ") + base_type);
        if (v.specific.empty()) unsupported(inst, std::string("complex ") + base_type + " without a knot subtype");
        if (base->params.size() != base_count)
            Params(file_, inst, base_type, {}).fail("has " + std::to_string(base->params.size()) +
                                                    " parameters, expected " + std::to_string(base_count));
        take(*base, 0, &v.base);
        const char* rational = surface ? "RATIONAL_B_SPLINE_SURFACE" : "RATIONAL_B_SPLINE_CURVE";
        if (const StepRecord* r = inst.record(rational)) {
            if (r->params.size() != 1) Params(file_, inst, rational, {}).fail("expected 1 parameter (weights_data)");
            v.weights = &r->params[0];
        }
        return v;
    }

    // The knot vector of one direction: from multiplicities and knots
    // (B_SPLINE_*_WITH_KNOTS) or implied by the subtype (ISO 10303-42: Bézier pieces on
    // 0, 1, .., k; quasi-uniform clamped on 0, 1, ..; uniform -p, .., n + 1).
    static std::vector<double> knot_vector(const Params& p, const std::string& specific, int degree, int count,
                                           const StepValue* mults, const StepValue* knots, const char* dir) {
        const std::string d(dir);
        std::vector<double> U;
        const int n = count - 1;
        if (specific.find("WITH_KNOTS") != std::string::npos) {
            const std::vector<StepValue>& M = p.list_of(*mults, (d + "multiplicities").c_str());
            const std::vector<StepValue>& K = p.list_of(*knots, (d + "knots").c_str());
            if (M.size() != K.size())
                p.fail(d + "multiplicities has " + std::to_string(M.size()) + " values but " + d + "knots " +
                       std::to_string(K.size()));
            long long sum = 0;
            for (const StepValue& m : M) {
                const long long x = p.integer_of(m, (d + "multiplicity").c_str());
                if (x < 1 || x > degree + 1)
                    p.fail(d + "multiplicity " + std::to_string(x) + " is outside 1.." + std::to_string(degree + 1));
                sum += x;
            }
            if (sum != static_cast<long long>(count) + degree + 1)
                p.fail(d + "multiplicities sum to " + std::to_string(sum) + ", expected " +
                       std::to_string(count + degree + 1) + " (degree " + std::to_string(degree) + ", " +
                       std::to_string(count) + " control points)");
            for (std::size_t i = 0; i < K.size(); ++i) {
                const double u = p.real_of(K[i], (d + "knot").c_str());
                if (i > 0 && u < U.back())
                    p.fail(d + "knots decrease: " + geom::format_value(u) + " after " + geom::format_value(U.back()));
                U.insert(U.end(), static_cast<std::size_t>(M[i].integer), u);
            }
        } else if (specific.rfind("BEZIER", 0) == 0) {
            if (n % degree != 0)
                p.fail(std::to_string(count) + " " + d + "control points do not make degree-" +
                       std::to_string(degree) + " Bezier pieces");
            const int pieces = n / degree;
            U.assign(degree + 1, 0.0);
            for (int k = 1; k < pieces; ++k) U.insert(U.end(), degree, static_cast<double>(k));
            U.insert(U.end(), degree + 1, static_cast<double>(pieces));
        } else if (specific.rfind("QUASI_UNIFORM", 0) == 0) {
            U.assign(degree + 1, 0.0);
            for (int k = 1; k <= n - degree; ++k) U.push_back(k);
            U.insert(U.end(), degree + 1, static_cast<double>(n - degree + 1));
        } else {
            for (int k = -degree; k <= n + 1; ++k) U.push_back(k);
        }
        return U;
    }

    static int degree_of(const Params& p, std::size_t i, const char* what, int count) {
        const long long deg = p.integer(i, what);
        if (deg < 1 || deg > geom::kMaxDegree)
            p.fail(std::string(what) + " " + std::to_string(deg) + " is outside 1.." +
                   std::to_string(geom::kMaxDegree));
        if (count < deg + 1)
            p.fail(std::to_string(count) + " control points are too few for " + what + " " + std::to_string(deg));
        return static_cast<int>(deg);
    }

    Vector3d point_ref(const Params& p, const StepValue& v) const {
        const long long id = p.reference_of(v, "control point");
        const StepInstance* q = file_.find(id);
        if (!q) p.fail("control point #" + std::to_string(id) + " is not defined");
        if (type_of(*q) != "CARTESIAN_POINT")
            p.fail("control point #" + std::to_string(id) + " is a " + type_of(*q) + ", expected CARTESIAN_POINT");
        return point(*q);
    }

    NurbsCurve3d bspline_curve(const StepInstance& inst) const {
        const BSplineValues v = bspline_values(inst, false);
        const Params p(file_, inst, v.specific, v.base);
        const std::vector<StepValue>& list = p.list(1, "control_points_list");
        const int count = static_cast<int>(list.size());
        const int degree = degree_of(p, 0, "degree", count);
        std::vector<Vector3d> P;
        for (const StepValue& x : list) P.push_back(point_ref(p, x));
        std::vector<double> U = knot_vector(p, v.specific, degree, count, v.knots.empty() ? nullptr : v.knots[0],
                                            v.knots.size() > 1 ? v.knots[1] : nullptr, "");
        std::vector<double> w;
        if (v.weights) {
            for (const StepValue& x : p.list_of(*v.weights, "weights_data")) w.push_back(p.real_of(x, "weight"));
            if (w.size() != P.size())
                p.fail(std::to_string(w.size()) + " weights for " + std::to_string(P.size()) + " control points");
        }
        try {
            return NurbsCurve3d(degree, std::move(U), std::move(P), std::move(w));
        } catch (const geom::InvalidInput& e) {
            p.fail(e.what());
        }
    }

    NurbsSurface bspline_surface(const StepInstance& inst, std::string* kind) const {
        const BSplineValues v = bspline_values(inst, true);
        const Params p(file_, inst, v.specific, v.base);
        const std::vector<StepValue>& rows = p.list(2, "control_points_list");
        const int nu = static_cast<int>(rows.size());
        if (nu == 0) p.fail("control_points_list is empty");
        const int nv = static_cast<int>(p.list_of(rows[0], "control point row").size());
        const int pu = degree_of(p, 0, "u_degree", nu), pv = degree_of(p, 1, "v_degree", nv);
        // Rows run along u (ISO 10303-42: control_points_list[i][j], i the u index);
        // NurbsSurface stores point (i, j) at i * nv + j: the same order.
        std::vector<Vector3d> P;
        P.reserve(static_cast<std::size_t>(nu) * nv);
        for (const StepValue& row : rows) {
            const std::vector<StepValue>& r = p.list_of(row, "control point row");
            if (static_cast<int>(r.size()) != nv)
                p.fail("control point rows have " + std::to_string(r.size()) + " and " + std::to_string(nv) +
                       " points");
            for (const StepValue& x : r) P.push_back(point_ref(p, x));
        }
        const bool knots = !v.knots.empty();
        std::vector<double> U = knot_vector(p, v.specific, pu, nu, knots ? v.knots[0] : nullptr,
                                            knots ? v.knots[2] : nullptr, "u_");
        std::vector<double> V = knot_vector(p, v.specific, pv, nv, knots ? v.knots[1] : nullptr,
                                            knots ? v.knots[3] : nullptr, "v_");
        std::vector<double> w;
        if (v.weights) {
            const std::vector<StepValue>& wrows = p.list_of(*v.weights, "weights_data");
            for (const StepValue& row : wrows)
                for (const StepValue& x : p.list_of(row, "weights row")) w.push_back(p.real_of(x, "weight"));
            if (wrows.size() != rows.size() || w.size() != P.size())
                p.fail("weights_data does not match the " + std::to_string(nu) + " x " + std::to_string(nv) +
                       " control points");
        }
        *kind = v.specific.rfind("BEZIER", 0) == 0 ? "bezier" : "bspline";
        try {
            return NurbsSurface(pu, pv, std::move(U), std::move(V), nu, nv, std::move(P), std::move(w));
        } catch (const geom::InvalidInput& e) {
            p.fail(e.what());
        }
    }

    // ---- edges ----

    NurbsCurve3d edge_curve(const StepInstance& inst, const Vector3d& start, const Vector3d& end, bool same_sense,
                            double tol, EdgeRange* range) const {
        const Curve c = curve(inst, 0);
        const Params p(file_, inst, type_of(inst), {});
        const bool coincide = (start - end).norm() <= tol;
        EdgeRange unused;
        EdgeRange& r = range ? *range : unused;
        try {
            switch (c.kind) {
                case Curve::Kind::kLine: {
                    if (coincide) p.fail("the edge's vertices coincide; a line has no closed piece");
                    const double ts = nearest_parameter(c, start), te = nearest_parameter(c, end);
                    if (ts == te) p.fail("the edge's vertices project to one point of the line");
                    r = {ts, te, 0.0};
                    return ts < te ? geom::line_segment(c.at(ts), c.at(te), ts, te)
                                   : geom::line_segment(c.at(ts), c.at(te), -ts, -te);
                }
                case Curve::Kind::kCircle:
                case Curve::Kind::kEllipse: {
                    const double ts = nearest_parameter(c, start), te = nearest_parameter(c, end);
                    // The forward sweep from start to end, in (0, 2π].
                    double sweep = kTwoPi;
                    if (!coincide) {
                        sweep = std::fmod(te - ts, kTwoPi);
                        if (sweep < 0) sweep += kTwoPi;
                        if (sweep <= geom::kAngleSlack) sweep = kTwoPi;
                    }
                    const double t1 = same_sense ? ts + sweep : ts - (coincide ? kTwoPi : kTwoPi - sweep);
                    // Part 42 4.4.x: a conic's parameter is its angle in the file's unit.
                    r = {ts / angle_factor_, t1 / angle_factor_, kTwoPi / angle_factor_};
                    return c.kind == Curve::Kind::kCircle ? geom::circular_arc(c.O, c.X, c.Y, c.a, ts, t1)
                                                          : geom::ellipse_arc(c.O, c.X, c.Y, c.a, c.b, ts, t1);
                }
                case Curve::Kind::kBounded: break;
            }
            return bounded_edge(c, p, start, end, same_sense, tol, r);
        } catch (const geom::InvalidInput& e) {
            p.fail(e.what());
        }
    }

    // edge_curve's piece of a bounded curve c (B-spline, polyline), its range in r.
    static NurbsCurve3d bounded_edge(const Curve& c, const Params& p, const Vector3d& start, const Vector3d& end,
                                     bool same_sense, double tol, EdgeRange& r) {
        const NurbsCurve3d& n = c.nurbs;
        // Plain variables, not a structured binding: the lambdas below capture them
        // (C++17 does not let lambdas capture bindings; clang refuses).
        const double a = n.domain().first, b = n.domain().second;
        const double eps = geom::kKnotTolerance * (b - a);
        const bool closed = (n.evaluate(a) - n.evaluate(b)).norm() <= tol;
        auto sub = [&](double x, double y) {
            if (x <= a + eps && y >= b - eps) return n;
            return n.sub_curve(std::max(x, a), std::min(y, b));
        };
        const double ts = nearest_parameter(c, start);
        if ((start - end).norm() <= tol) {
            if (!closed) p.fail("the edge's vertices coincide but the curve is open");
            const bool at_end = ts <= a + eps || ts >= b - eps;
            r = at_end ? EdgeRange{a, b, b - a} : EdgeRange{ts, ts + (b - a), b - a};
            if (!same_sense) std::swap(r.start, r.end);
            const NurbsCurve3d whole = at_end ? n : joined(sub(ts, b), sub(a, ts));
            return same_sense ? whole : whole.reversed();
        }
        const double te = nearest_parameter(c, end);
        // The parameters the piece from x to y runs between (forward below).
        auto span = [&](double x, double y) {
            if (closed && x >= b - eps) x = a;
            if (closed && y <= a + eps) y = b;
            if (closed && y <= x + eps) y += b - a;  // across the curve's ends
            return EdgeRange{x, y, closed ? b - a : 0.0};
        };
        // The piece following the curve from parameter x to y.
        auto forward = [&](double x, double y) -> NurbsCurve3d {
            if (closed && x >= b - eps) x = a;
            if (closed && y <= a + eps) y = b;
            if (y > x + eps) return sub(x, y);
            if (closed) return joined(sub(x, b), sub(a, y));
            if (x > y + eps) return sub(y, x).reversed();  // against same_sense: cut anyway
            p.fail("the edge's vertices meet the open curve at one point");
        };
        r = same_sense ? span(ts, te) : span(te, ts);
        if (!same_sense) std::swap(r.start, r.end);
        return same_sense ? forward(ts, te) : forward(te, ts).reversed();
    }

    // ---- parameter-space curves ----

    // edge_pcurve without the catch: throws for a malformed entity.
    std::optional<NurbsCurve2d> edge_pcurve(const StepInstance& geometry, long long surface_id,
                                            const EdgeRange& range, bool first_of_seam) const {
        const std::string type = type_of(geometry);
        if (type != "SURFACE_CURVE" && type != "SEAM_CURVE") return std::nullopt;
        const Params p = simple(geometry, 3);
        // associated_geometry: PCURVEs or SURFACEs (pcurve_or_surface); only PCURVEs here.
        std::vector<const StepInstance*> on_surface;
        for (const StepValue& v : p.list(1, "associated_geometry")) {
            const StepInstance* pc = v.kind == StepValue::Kind::kReference ? file_.find(v.integer) : nullptr;
            if (!pc || type_of(*pc) != "PCURVE") continue;
            if (simple(*pc, 2).reference(0, "basis_surface") == surface_id) on_surface.push_back(pc);
        }
        if (on_surface.empty()) return std::nullopt;
        const Params pc = simple(*on_surface[!first_of_seam && on_surface.size() > 1 ? 1 : 0], 2);
        const Params rep = simple(referred(pc, 1, "reference_to_curve", {"DEFINITIONAL_REPRESENTATION"}), 2);
        const std::vector<StepValue>& items = rep.list(0, "items");
        if (items.empty()) return std::nullopt;
        const StepInstance* item = file_.find(rep.reference_of(items[0], "item"));
        if (!item) return std::nullopt;
        return plane_piece(curve(*item, 0), range);
    }

    // The piece of a curve in the plane z = 0 between the parameters of `range` (in the
    // file's units), running from range.start to range.end, as a 2D curve; nullopt when
    // the curve leaves z = 0 or a bounded curve does not cover the range.
    std::optional<NurbsCurve2d> plane_piece(const Curve& c, const EdgeRange& range) const {
        double lo = std::min(range.start, range.end), hi = std::max(range.start, range.end);
        if (!(hi > lo)) return std::nullopt;
        NurbsCurve3d n;
        if (c.kind == Curve::Kind::kLine) {
            n = geom::line_segment(c.at(lo), c.at(hi), lo, hi);
        } else if (c.conic()) {
            // Part 42 4.4.x: a conic's parameter is its angle in the file's unit.
            const double t0 = lo * angle_factor_, t1 = hi * angle_factor_;
            n = c.kind == Curve::Kind::kCircle ? geom::circular_arc(c.O, c.X, c.Y, c.a, t0, t1)
                                               : geom::ellipse_arc(c.O, c.X, c.Y, c.a, c.b, t0, t1);
        } else {
            const double a = c.nurbs.domain().first, b = c.nurbs.domain().second;
            const double eps = kPcurveRangeSlack * (b - a);
            if (range.period > 0) {
                const double k = std::ceil((a - eps - lo) / range.period);
                lo += k * range.period;
                hi += k * range.period;
            }
            if (lo < a - eps || hi > b + eps) return std::nullopt;
            lo = std::max(lo, a);
            hi = std::min(hi, b);
            // sub_curve also clamps an unclamped knot vector (a periodic curve's).
            const bool whole = lo <= a + geom::kKnotTolerance * (b - a) && hi >= b - geom::kKnotTolerance * (b - a);
            n = whole && geom::is_clamped(c.nurbs.knots(), c.nurbs.degree()) ? c.nurbs : c.nurbs.sub_curve(lo, hi);
        }
        std::vector<Vector2d> P;
        for (const Vector3d& x : n.points()) {
            if (x.z() != 0.0) return std::nullopt;  // 2D points and placements give z = 0 exactly
            P.emplace_back(x.x(), x.y());
        }
        NurbsCurve2d out(n.degree(), n.knots(), std::move(P), n.is_rational() ? n.weights() : std::vector<double>{});
        return range.end < range.start ? out.reversed() : out;
    }

    // ---- surfaces ----

    Elementary elementary(const StepInstance& inst) const {
        const std::string type = type_of(inst);
        Elementary e;
        using K = Elementary::Kind;
        const bool torus = type == "TOROIDAL_SURFACE", degenerate = type == "DEGENERATE_TOROIDAL_SURFACE";
        std::size_t count = 2;
        if (type == "PLANE") {
            e.kind = K::kPlane;
            count = 1;
        } else if (type == "CYLINDRICAL_SURFACE") {
            e.kind = K::kCylinder;
        } else if (type == "CONICAL_SURFACE") {
            e.kind = K::kCone;
            count = 3;
        } else if (type == "SPHERICAL_SURFACE") {
            e.kind = K::kSphere;
        } else if (torus || degenerate) {
            e.kind = K::kTorus;
            count = degenerate ? 4 : 3;
        }
        const Params p = simple(inst, count);
        e.f = placement(referred(p, 0, "position", {"AXIS2_PLACEMENT_3D"}));
        if (e.kind == K::kPlane) return e;
        const char* first = e.kind == K::kTorus ? "major_radius" : "radius";
        e.r = p.real(1, first);
        if (e.kind == K::kCone ? !(e.r >= 0) : !(e.r > 0))
            p.fail(std::string(first) + " " + geom::format_value(e.r) + " must be " +
                   (e.kind == K::kCone ? ">= 0" : "> 0"));
        if (e.kind == K::kCone) {
            e.alpha = p.real(2, "semi_angle") * angle_factor_;
            if (!(e.alpha > 0 && e.alpha < 0.5 * kPi))
                p.fail("semi_angle " + geom::format_value(e.alpha) + " rad is outside (0, pi/2)");
        }
        if (e.kind == K::kTorus) {
            e.minor = p.real(2, "minor_radius");
            if (!(e.minor > 0)) p.fail("minor_radius " + geom::format_value(e.minor) + " must be > 0");
            if (degenerate) {
                if (!(e.r < e.minor)) p.fail("major_radius is not below minor_radius");
                e.part = p.boolean(3, "select_outer") ? 1 : -1;
            }
        }
        return e;
    }

    static bool is_elementary(const std::string& type) {
        return type == "PLANE" || type == "CYLINDRICAL_SURFACE" || type == "CONICAL_SURFACE" ||
               type == "SPHERICAL_SURFACE" || type == "TOROIDAL_SURFACE" || type == "DEGENERATE_TOROIDAL_SURFACE";
    }

    static geom::AxisMap arc_axis(double theta0, double theta1) {
        geom::AxisMap m;
        m.arc.emplace(theta0, theta1);
        return m;
    }

    Surface build(const Elementary& e, const std::vector<Vector3d>& boundary, const Params& p) const {
        using K = Elementary::Kind;
        const Frame& f = e.f;
        std::vector<Vector3d> q;  // boundary in the frame
        q.reserve(boundary.size());
        for (const Vector3d& x : boundary) q.emplace_back((x - f.O).dot(f.X), (x - f.O).dot(f.Y), (x - f.O).dot(f.Z));
        auto coordinate = [&](int k) {
            std::vector<double> v;
            for (const Vector3d& x : q) v.push_back(x[k]);
            return v;
        };
        if ((e.kind == K::kPlane || e.kind == K::kCylinder || e.kind == K::kCone) && q.empty())
            p.fail("an unbounded surface needs boundary points to size it");
        const double size = e.r + e.minor + 1e-300;
        // A torus point lies across the axis from its circle's centre (at θ + π, signed
        // distance -ρ) where R + r cos φ < 0: on a degenerate torus's inner part, and on
        // the spindle part of a TOROIDAL_SURFACE with R < r when that fits it better.
        std::vector<int> across;
        for (const Vector3d& x : q) {
            int s = e.part < 0 ? -1 : 1;
            if (e.kind == K::kTorus && e.part == 0 && e.r < e.minor) {
                const double rho = std::hypot(x.x(), x.y());
                const double near = std::fabs(std::hypot(rho - e.r, x.z()) - e.minor);
                const double far = std::fabs(std::hypot(rho + e.r, x.z()) - e.minor);
                if (far < near) s = -1;
            }
            across.push_back(s);
        }
        // Longitude of each point (NaN on the axis).
        std::vector<double> theta;
        for (std::size_t k = 0; k < q.size(); ++k) {
            const Vector3d& x = q[k];
            const double rho = std::hypot(x.x(), x.y());
            double t = rho <= kOnAxisShare * (size + std::fabs(x.z())) ? kNaN : std::atan2(x.y(), x.x());
            if (across[k] < 0) t += kPi;
            theta.push_back(t);
        }
        Surface out;
        if (e.kind == K::kPlane) {
            const auto [u0, u1] = padded_extent(coordinate(0), kStepBoundaryMargin);
            const auto [v0, v1] = padded_extent(coordinate(1), kStepBoundaryMargin);
            out.nurbs = geom::plane_patch(f.O, f.X, f.Y, u0, u1, v0, v1);
            out.kind = "plane";
            return out;
        }
        const AngularExtent around = whole_turn(angular_extent(theta, kStepBoundaryMargin));
        out.map.u = arc_axis(around.lo, around.hi);
        if (e.kind == K::kCylinder) {
            const auto [z0, z1] = padded_extent(coordinate(2), kStepBoundaryMargin);
            out.nurbs = geom::cylinder_patch(f.O, f.Z, f.X, e.r, around.lo, around.hi, z0, z1);
            out.kind = "cylinder";
            return out;
        }
        if (e.kind == K::kCone) {
            const std::vector<double> z = coordinate(2);
            const double apex = -e.r / std::tan(e.alpha);
            const double zmin = *std::min_element(z.begin(), z.end()), zmax = *std::max_element(z.begin(), z.end());
            auto [z0, z1] = padded_extent(z, kStepBoundaryMargin);
            if (around.full && zmax - zmin <= kOneHeightShare * (e.r + std::fabs(zmin) + std::fabs(zmax))) {
                // A cap: from its parallel to the apex.
                if (zmin >= apex) z0 = apex;
                else z1 = apex;
            } else if (apex > z0 && apex < z1) {
                // The margin must not carry the range past the apex onto the other nappe.
                (apex - z0 > z1 - apex ? z1 : z0) = apex;
            }
            out.nurbs = geom::cone_patch(f.O, f.Z, f.X, e.r, e.alpha, around.lo, around.hi, z0, z1);
            out.kind = "cone";
            return out;
        }
        if (e.kind == K::kSphere) {
            // Pole to pole: the boundary cannot tell which side of it the face is (a
            // sphere less a corner: the boundary lies by the cut, the face reaches the
            // far pole).
            const double phi0 = -0.5 * kPi, phi1 = 0.5 * kPi;
            out.nurbs = geom::sphere_patch(f.O, f.Z, f.X, e.r, around.lo, around.hi, phi0, phi1);
            out.kind = "sphere";
            out.map.v = arc_axis(phi0, phi1);
            return out;
        }
        // Torus: φ about the tube, from the point's distance to the axis (signed:
        // negative across the axis on a degenerate torus's inner part) and height.
        std::vector<double> phi;
        for (std::size_t k = 0; k < q.size(); ++k) {
            const Vector3d& x = q[k];
            const double rho = across[k] * std::hypot(x.x(), x.y());
            double t = std::atan2(x.z(), rho - e.r);
            if (e.part < 0 && t < 0) t += kTwoPi;
            phi.push_back(t);
        }
        double phi0 = 0, phi1 = kTwoPi;
        if (e.part != 0) {
            // The part's own range: R + r cos φ >= 0 (outer) or <= 0 (inner).
            const double limit = std::acos(-e.r / e.minor);
            phi0 = e.part > 0 ? -limit : limit;
            phi1 = e.part > 0 ? limit : kTwoPi - limit;
            if (!phi.empty()) {
                const auto [lo, hi] = padded_extent(phi, kStepBoundaryMargin);
                phi0 = std::max(phi0, lo);
                phi1 = std::min(phi1, hi);
            }
        } else {
            const AngularExtent tube = whole_turn(angular_extent(phi, kStepBoundaryMargin));
            phi0 = tube.lo;
            phi1 = tube.hi;
        }
        out.nurbs = geom::torus_patch(f.O, f.Z, f.X, e.r, e.minor, around.lo, around.hi, phi0, phi1);
        out.kind = "torus";
        out.map.v = arc_axis(phi0, phi1);
        return out;
    }

    // The swept curve over the parameters `t` the boundary covers (bounded: whole),
    // and the map from its parameter to the NURBS's.
    std::pair<NurbsCurve3d, geom::AxisMap> swept_piece(const Curve& c, const std::vector<double>& t,
                                                       const Params& p) const {
        if (c.kind == Curve::Kind::kBounded) return {c.nurbs, {}};
        if (t.empty()) p.fail("an unbounded swept curve needs boundary points to size it");
        if (c.kind == Curve::Kind::kLine) {
            const auto [t0, t1] = padded_extent(t, kStepBoundaryMargin);
            return {geom::line_segment(c.at(t0), c.at(t1), t0, t1), {}};
        }
        const AngularExtent e = whole_turn(angular_extent(t, kStepBoundaryMargin));
        NurbsCurve3d n = c.kind == Curve::Kind::kCircle ? geom::circular_arc(c.O, c.X, c.Y, c.a, e.lo, e.hi)
                                                        : geom::ellipse_arc(c.O, c.X, c.Y, c.a, c.b, e.lo, e.hi);
        return {std::move(n), arc_axis(e.lo, e.hi)};
    }

    Surface revolution(const Params& p, const std::vector<Vector3d>& boundary, int depth) const {
        const Curve g = curve(defined(p, 0, "swept_curve"), depth + 1);
        const Frame axis = placement(referred(p, 1, "axis_position", {"AXIS1_PLACEMENT"}));
        const Vector3d A = axis.O, a = axis.Z;
        auto meridian = [&](const Vector3d& x) {
            const double h = (x - A).dot(a);
            return std::pair{h, ((x - A) - h * a).norm()};
        };
        const double size = g.size() + A.norm();
        const std::vector<double> grid = g.kind == Curve::Kind::kLine ? std::vector<double>{} : g.grid();
        std::vector<double> t, theta;
        for (const Vector3d& x : boundary) {
            const std::pair<double, double> hr = meridian(x);  // named: the lambda below captures them
            const double h = hr.first, rho = hr.second;
            // The generatrix parameter whose circle about the axis passes through x.
            double s = 0;
            if (g.kind == Curve::Kind::kLine) {
                const double da = g.X.dot(a);
                if (std::fabs(da) > geom::kAnalyticTolerance * g.X.norm()) {
                    s = (h - (g.O - A).dot(a)) / da;
                } else {
                    // A line square to the axis: |w + s d| = rho, both roots.
                    const Vector3d w = (g.O - A) - (g.O - A).dot(a) * a;
                    const double qa = g.X.squaredNorm(), qb = w.dot(g.X), qc = w.squaredNorm() - rho * rho;
                    const double disc = std::max(0.0, qb * qb - qa * qc);
                    s = (-qb + std::sqrt(disc)) / qa;
                    t.push_back((-qb - std::sqrt(disc)) / qa);
                    theta.push_back(kNaN);
                }
            } else {
                s = minimise(grid, [&](double u) {
                    const auto [hu, ru] = meridian(g.at(u));
                    return (hu - h) * (hu - h) + (ru - rho) * (ru - rho);
                });
            }
            t.push_back(s);
            // The angle turning the generatrix point onto x.
            const Vector3d c = g.at(s) - A, r_g = c - c.dot(a) * a, r_x = (x - A) - h * a;
            const double small = kOnAxisShare * size;
            theta.push_back(r_g.norm() <= small || r_x.norm() <= small
                                ? kNaN
                                : std::atan2(a.dot(r_g.cross(r_x)), r_g.dot(r_x)));
        }
        auto [gen, gen_map] = swept_piece(g, t, p);
        const AngularExtent around = whole_turn(angular_extent(theta, kStepBoundaryMargin));
        Surface out;
        out.nurbs = geom::surface_of_revolution(gen, A, a, around.lo, around.hi);
        out.kind = "revolution";
        out.map.swap = true;  // STEP (angle, curve parameter); ours (curve parameter, angle)
        out.map.u = gen_map;
        out.map.v = arc_axis(around.lo, around.hi);
        return out;
    }

    Surface extrusion(const Params& p, const std::vector<Vector3d>& boundary, int depth) const {
        const Curve g = curve(defined(p, 0, "swept_curve"), depth + 1);
        const Vector3d V = vector(referred(p, 1, "extrusion_axis", {"VECTOR"}));
        if (boundary.empty()) p.fail("an unbounded surface needs boundary points to size it");
        const Vector3d n = V.normalized();
        auto across = [&](const Vector3d& x) -> Vector3d { return x - x.dot(n) * n; };
        const std::vector<double> grid = g.kind == Curve::Kind::kLine ? std::vector<double>{} : g.grid();
        std::vector<double> t, v;
        for (const Vector3d& x : boundary) {
            // The directrix parameter whose ruling passes through x.
            double s = 0;
            if (g.kind == Curve::Kind::kLine) {
                const Vector3d d = across(g.X);
                if (d.norm() <= geom::kAnalyticTolerance * g.X.norm()) p.fail("the swept line is parallel to the extrusion");
                s = across(x - g.O).dot(d) / d.squaredNorm();
            } else {
                s = minimise(grid, [&](double u) { return across(g.at(u) - x).squaredNorm(); });
            }
            t.push_back(s);
            v.push_back((x - g.at(s)).dot(V) / V.squaredNorm());
        }
        auto [dir, dir_map] = swept_piece(g, t, p);
        const auto [v0, v1] = padded_extent(v, kStepBoundaryMargin);
        Surface out;
        out.nurbs = geom::tabulated_cylinder(dir, V, v0, v1);
        out.kind = "extrusion";
        out.map.u = dir_map;
        return out;
    }

    Surface surface(const StepInstance& inst, const std::vector<Vector3d>& boundary, int depth) const {
        const std::string type = type_of(inst);
        Params p(file_, inst, type, {});
        try {
            if (inst.records.size() > 1 || std::find(std::begin(kSimpleBSplineSurfaces), std::end(kSimpleBSplineSurfaces),
                                                     type) != std::end(kSimpleBSplineSurfaces)) {
                if (inst.records.size() > 1 && !inst.record("B_SPLINE_SURFACE")) unsupported(inst, "complex surface");
                Surface out;
                out.nurbs = bspline_surface(inst, &out.kind);
                return out;
            }
            if (is_elementary(type)) return build(elementary(inst), boundary, p);
            if (type == "SURFACE_OF_REVOLUTION") return revolution(simple(inst, 2), boundary, depth);
            if (type == "SURFACE_OF_LINEAR_EXTRUSION") return extrusion(simple(inst, 2), boundary, depth);
            if (type == "RECTANGULAR_TRIMMED_SURFACE") {
                const Params r = simple(inst, 7);
                check_depth(r, depth);
                return surface(defined(r, 0, "basis_surface"), boundary, depth + 1);
            }
            if (type == "OFFSET_SURFACE") {
                const Params r = simple(inst, 3);
                check_depth(r, depth);
                const StepInstance& basis = defined(r, 0, "basis_surface");
                if (!is_elementary(type_of(basis))) unsupported(inst, "offset of a " + type_of(basis));
                Elementary e = elementary(basis);
                if (e.part != 0) unsupported(inst, "offset of a degenerate torus");
                offset(&e, r.real(1, "distance"), r);
                Surface out = build(e, boundary, r);
                out.kind = "offset";
                return out;
            }
        } catch (const geom::InvalidInput& e) {
            p.fail(e.what());
        } catch (const geom::NumericalFailure& e) {
            p.fail(e.what());
        }
        unsupported(inst, "surface kind not translated");
    }

    // The surface at signed distance d along the unit normal Su × Sv of e's STEP
    // parameterisation (outwards from the axis or centre; the plane's Z): again
    // elementary. Cone: the normal leans back by α, so the radius at the location
    // grows by d / cos α.
    static void offset(Elementary* e, double d, const Params& p) {
        using K = Elementary::Kind;
        switch (e->kind) {
            case K::kPlane: e->f.O += d * e->f.Z; return;
            case K::kCylinder:
            case K::kSphere: e->r += d; break;
            case K::kCone: e->r += d / std::cos(e->alpha); break;
            case K::kTorus: e->minor += d; break;
        }
        if (!(e->r >= 0) || (e->kind != K::kCone && !(e->r > 0)) || (e->kind == K::kTorus && !(e->minor > 0)))
            p.fail("distance " + geom::format_value(d) + " collapses the basis surface");
    }

private:
    const StepPart21& file_;
    double angle_factor_;
};

}  // namespace

StepGeometry::StepGeometry(const StepPart21& file, double plane_angle_to_radians)
    : file_(file), angle_factor_(plane_angle_to_radians) {
    if (!(plane_angle_to_radians > 0) || !std::isfinite(plane_angle_to_radians))
        throw geom::InvalidInput("StepGeometry: plane_angle_to_radians = " + geom::format_value(plane_angle_to_radians) +
                                 "; expected a finite value > 0");
}

Vector3d StepGeometry::point(long long id) const {
    const Translator t(file_, angle_factor_);
    return t.point(t.top(id));
}

Vector3d StepGeometry::direction(long long id) const {
    const Translator t(file_, angle_factor_);
    return t.direction(t.top(id));
}

Vector3d StepGeometry::vector(long long id) const {
    const Translator t(file_, angle_factor_);
    return t.vector(t.top(id));
}

Eigen::Affine3d StepGeometry::placement(long long id) const {
    const Translator t(file_, angle_factor_);
    const Frame f = t.placement(t.top(id));
    Eigen::Affine3d M = Eigen::Affine3d::Identity();
    M.linear().col(0) = f.X;
    M.linear().col(1) = f.Y;
    M.linear().col(2) = f.Z;
    M.translation() = f.O;
    return M;
}

NurbsCurve3d StepGeometry::edge_curve(long long curve_id, const Vector3d& start, const Vector3d& end,
                                      bool same_sense, double tol, EdgeRange* range) const {
    const Translator t(file_, angle_factor_);
    return t.edge_curve(t.top(curve_id), start, end, same_sense, tol, range);
}

std::optional<NurbsCurve2d> StepGeometry::edge_pcurve(long long curve_id, long long surface_id,
                                                      const EdgeRange& range, bool first_of_seam) const {
    const StepInstance* geometry = file_.find(curve_id);
    if (!geometry) return std::nullopt;
    try {
        return Translator(file_, angle_factor_).edge_pcurve(*geometry, surface_id, range, first_of_seam);
    } catch (const std::runtime_error&) {  // ReadError, UnsupportedStepEntity, NumericalFailure
    } catch (const std::logic_error&) {    // InvalidInput, out_of_range
    }
    return std::nullopt;
}

namespace {

// Moves the angle coordinate d of P by whole turns into the arc's turn. A whole-turn
// arc [θ0, θ1]: only a curve starting below θ0 or past θ1 moves, to start within it
// (AxisMap::period continues it past θ1); one on θ1 stays there, on the seam side the
// file put it (a seam's two PCURVEs at θ0 and θ1). Another arc: the turn whose middle
// is nearest the arc's. Angles in the axis's source units (before scale and offset).
void into_turn(std::vector<Vector2d>& P, int d, const geom::AxisMap& axis) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const Vector2d& x : P) {
        lo = std::min(lo, axis.scale * x[d] + axis.offset);
        hi = std::max(hi, axis.scale * x[d] + axis.offset);
    }
    const double t0 = std::min(axis.arc->theta0(), axis.arc->theta1());
    const double t1 = std::max(axis.arc->theta0(), axis.arc->theta1());
    const double slack = kTurnSlack * kTwoPi;
    double k = 0;
    if (axis.period <= 0) k = std::round((0.5 * (t0 + t1) - 0.5 * (lo + hi)) / kTwoPi);
    else if (lo < t0 - slack) k = std::ceil((t0 - slack - lo) / kTwoPi);
    else if (lo > t1 + slack) k = -std::floor((lo - t0 + slack) / kTwoPi);
    if (k == 0 || !std::isfinite(k)) return;
    for (Vector2d& x : P) x[d] += k * kTwoPi / axis.scale;
}

}  // namespace

std::optional<NurbsCurve2d> StepGeometry::map_pcurve(const Surface& S, const NurbsCurve2d& c) const {
    geom::ParameterMap map = S.map;
    std::vector<Vector2d> P = c.points();
    for (int d = 0; d < 2; ++d) {
        geom::AxisMap& axis = (d == 0) != map.swap ? map.u : map.v;  // swap: s maps to v
        if (!axis.arc || axis.scale == 0) continue;
        for (Vector2d& x : P) x[d] *= angle_factor_;  // plane angles in the file's unit
        if (std::fabs(axis.arc->theta1() - axis.arc->theta0()) >= kTwoPi - geom::kAngleSlack) axis.period = kTwoPi;
        into_turn(P, d, axis);
    }
    try {
        const NurbsCurve2d radians(c.degree(), c.knots(), std::move(P),
                                   c.is_rational() ? c.weights() : std::vector<double>{});
        const auto [u0, u1] = S.nurbs.domain_u();
        const auto [v0, v1] = S.nurbs.domain_v();
        return map.map_curve(radians, kPcurveRefitShare * std::max(u1 - u0, v1 - v0));
    } catch (const std::runtime_error&) {
    } catch (const std::logic_error&) {
    }
    return std::nullopt;
}

StepGeometry::Surface StepGeometry::surface(long long id, const std::vector<Vector3d>& boundary) const {
    const Translator t(file_, angle_factor_);
    return t.surface(t.top(id), boundary, 0);
}

void unsupported_step_entity(const StepPart21& file, const StepInstance& at, const std::string& why) {
    throw UnsupportedStepEntity(file.name() + ":" + std::to_string(at.line) + ": #" + std::to_string(at.id) + " " +
                                type_of(at) + ": " + why);
}

}  // namespace trimkit::io
