#include "geom/parameter_map.h"

#include <cmath>
#include <utility>

#include "geom/curve_interpolation.h"

namespace trimkit::geom {

double AxisMap::apply(double x) const {
    const double y = scale * x + offset;
    if (!arc) return y;
    if (period > 0.0) {
        const double k = std::floor((y - arc->theta0()) / period);
        if (k > 0.0) return arc->to_nurbs(y - k * period) + k * period;
    }
    return arc->to_nurbs(y);
}

Eigen::Vector2d ParameterMap::apply(Eigen::Vector2d st) const {
    if (swap) std::swap(st.x(), st.y());
    return {u.apply(st.x()), v.apply(st.y())};
}

bool ParameterMap::identity() const {
    return !swap && affine() && u.scale == 1.0 && u.offset == 0.0 && v.scale == 1.0 && v.offset == 0.0;
}

namespace {

// Turns of a wound axis whose knot angles become refit breaks.
constexpr int kMaxTurns = 4;

// True when c is a polyline of axis-parallel segments: the map works on each axis
// alone and keeps its order, so the image of such a segment is the segment between
// the mapped end points, and mapping the points maps the trace exactly (only the
// speed along it changes, which trimming does not see).
bool axis_parallel_polyline(const NurbsCurve2d& c) {
    if (c.degree() != 1) return false;
    const auto& P = c.points();
    for (std::size_t i = 1; i < P.size(); ++i) {
        const Eigen::Vector2d d = P[i] - P[i - 1];
        const double tol = 1e-12 * (1.0 + P[i].cwiseAbs().maxCoeff());
        if (std::fabs(d.x()) > tol && std::fabs(d.y()) > tol) return false;
    }
    return true;
}

// The source-plane values x at which an axis map is only C1 (its arc's interior
// knot angles, pulled back through the affine part).
std::vector<double> source_breaks(const AxisMap& a) {
    std::vector<double> out;
    if (!a.arc || a.scale == 0.0) return out;
    const auto& angles = a.arc->angles();
    const int turns = a.period > 0.0 ? kMaxTurns : 1;
    for (int k = 0; k < turns; ++k)
        for (std::size_t i = k == 0 ? 1 : 0; i + 1 < angles.size(); ++i)
            out.push_back((angles[i] + k * a.period - a.offset) / a.scale);
    return out;
}

}  // namespace

NurbsCurve2d ParameterMap::map_curve(const NurbsCurve2d& c, double tolerance) const {
    if (identity()) return c;
    if (affine() || axis_parallel_polyline(c)) {
        std::vector<Eigen::Vector2d> P;
        P.reserve(c.points().size());
        for (const Eigen::Vector2d& p : c.points()) P.push_back(apply(p));
        return NurbsCurve2d(c.degree(), c.knots(), std::move(P),
                            c.is_rational() ? c.weights() : std::vector<double>{});
    }
    MapBreaks breaks;
    breaks.u = source_breaks(swap ? v : u);
    breaks.v = source_breaks(swap ? u : v);
    return refit_mapped_curve(c, [this](Eigen::Vector2d p) { return apply(p); }, tolerance, breaks);
}

}  // namespace trimkit::geom
