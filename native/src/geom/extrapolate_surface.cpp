#include "geom/extrapolate_surface.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "geom/error.h"
#include "geom/knot_vector.h"

namespace trimkit::geom {
namespace {

using Vector4d = Eigen::Vector4d;

// The control polygon over [0, s] of the Bézier curve with polygon `P` over [0, 1]:
// the first points of de Casteljau's levels at s (any s, here s > 1).
std::vector<Vector4d> continued(std::vector<Vector4d> P, double s) {
    std::vector<Vector4d> out{P.front()};
    for (size_t level = 1; level < P.size(); ++level) {
        for (size_t k = 0; k + level < P.size(); ++k) P[k] = (1 - s) * P[k] + s * P[k + 1];
        out.push_back(P.front());
    }
    return out;
}

// Multiplicity of knot value x in U.
int multiplicity(const std::vector<double>& U, double x) {
    return static_cast<int>(std::count(U.begin(), U.end(), x));
}

// S with its u domain's end moved to `to` (> the end) when `at_end`, else its start
// moved to `to` (< the start), by continuing the end span.
NurbsSurface continue_u(const NurbsSurface& S, double to, bool at_end) {
    const int p = S.degree_u();
    const auto [a0, a1] = S.domain_u();
    // The knot that bounds the end span on the inside, raised to multiplicity p.
    const std::vector<double>& U0 = S.knots_u();
    double inner = at_end ? a0 : a1;
    for (double x : U0)
        if (x > a0 && x < a1) inner = at_end ? std::max(inner, x) : std::min(inner, x);
    NurbsSurface R = S;
    if (inner > a0 && inner < a1) {
        const int have = multiplicity(U0, inner);
        if (have < p) R = R.insert_knot_u(inner, p - have);
    }
    const int nu = R.count_u(), nv = R.count_v();
    std::vector<Eigen::Vector3d> P = R.points();
    std::vector<double> w = R.is_rational() ? R.weights() : std::vector<double>(P.size(), 1.0);
    const double edge = at_end ? a1 : a0;
    const double s = (to - inner) / (edge - inner);
    for (int j = 0; j < nv; ++j) {
        std::vector<Vector4d> span;
        for (int k = 0; k <= p; ++k) {
            const int i = at_end ? nu - 1 - p + k : p - k;  // from the inner knot outwards
            const double wi = w[i * nv + j];
            span.push_back(Vector4d(wi * P[i * nv + j].x(), wi * P[i * nv + j].y(), wi * P[i * nv + j].z(), wi));
        }
        const std::vector<Vector4d> wide = continued(span, s);
        for (int k = 0; k <= p; ++k) {
            const int i = at_end ? nu - 1 - p + k : p - k;
            if (!(wide[k].w() > 0.0))
                throw NumericalFailure("extrapolated_surface: a weight reaches " + format_value(wide[k].w()) +
                                       " on the widened span");
            P[i * nv + j] = wide[k].head<3>() / wide[k].w();
            w[i * nv + j] = wide[k].w();
        }
    }
    std::vector<double> U = R.knots_u();
    if (at_end) {
        for (int k = 0; k <= p; ++k) U[U.size() - 1 - k] = to;
    } else {
        for (int k = 0; k <= p; ++k) U[k] = to;
    }
    return NurbsSurface(p, R.degree_v(), std::move(U), R.knots_v(), nu, nv, std::move(P),
                        R.is_rational() ? std::move(w) : std::vector<double>{});
}

}  // namespace

NurbsSurface extrapolated_surface(const NurbsSurface& S, double u0, double u1, double v0, double v1) {
    if (!std::isfinite(u0) || !std::isfinite(u1) || !std::isfinite(v0) || !std::isfinite(v1))
        throw InvalidInput("extrapolated_surface: bounds must be finite");
    // An unclamped knot vector (uniform knots past the domain, OCCT's non-periodic
    // B-splines through its STEP writer) is clamped to the domain first: its last
    // poles are not its end span's (shell1.brep via STEP: the face became the whole
    // control net's patch, 10x its area, 293 T off).
    NurbsSurface R = S;
    if (!is_clamped(S.knots_u(), S.degree_u()) || !is_clamped(S.knots_v(), S.degree_v())) {
        const auto [du0, du1] = S.domain_u();
        const auto [dv0, dv1] = S.domain_v();
        R = S.sub_surface(du0, du1, dv0, dv1);
    }
    if (u1 > R.domain_u().second) R = continue_u(R, u1, true);
    if (u0 < R.domain_u().first) R = continue_u(R, u0, false);
    if (v1 > R.domain_v().second) R = continue_u(R.swapped_uv(), v1, true).swapped_uv();
    if (v0 < R.domain_v().first) R = continue_u(R.swapped_uv(), v0, false).swapped_uv();
    return R;
}

}  // namespace trimkit::geom
