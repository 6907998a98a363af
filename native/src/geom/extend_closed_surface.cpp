#include "geom/extend_closed_surface.h"

#include <cmath>
#include <string>
#include <vector>

#include "geom/error.h"
#include "geom/knot_vector.h"
#include "geom/clamped_int.h"

namespace trimkit::geom {
namespace {

// Weights of the two boundary rows agree up to one factor within this relative
// difference (weights are read to ~1e-15; a real mismatch is far larger).
constexpr double kWeightRatioTolerance = 1e-9;

bool clamped_u(const NurbsSurface& s) {
    const std::vector<double>& U = s.knots_u();
    const int p = s.degree_u();
    return U[0] == U[p] && U[U.size() - 1] == U[U.size() - 1 - p];
}

// s with clamped u ends (same geometry and domain), so its first and last rows
// are the boundary curves' control points.
NurbsSurface clamp_u(const NurbsSurface& s) {
    if (clamped_u(s)) return s;
    const auto [u0, u1] = s.domain_u();
    const auto [v0, v1] = s.domain_v();
    return s.sub_surface(u0, u1, v0, v1);
}

// The last row's weights over the first row's (one factor for the whole row), or
// a negative value when the rows are not the same curve within `tolerance`.
double closure_ratio(const NurbsSurface& s, double tolerance) {
    const int last = s.count_u() - 1;
    const double k = s.weight(last, 0) / s.weight(0, 0);
    for (int j = 0; j < s.count_v(); ++j) {
        if (!((s.point(0, j) - s.point(last, j)).norm() <= tolerance)) return -1.0;
        if (std::abs(s.weight(last, j) - k * s.weight(0, j)) > kWeightRatioTolerance * s.weight(last, j))
            return -1.0;
    }
    return k;
}

// The extension along u; extend_closed_surface swaps for v.
NurbsSurface extend_u(const NurbsSurface& input, double a, double b, double tolerance) {
    const auto [u0, u1] = input.domain_u();
    const auto [v0, v1] = input.domain_v();
    if (!(a < b))
        throw InvalidInput("extend_closed_surface: range [" + format_value(a) + ", " + format_value(b) +
                           "]; expected a < b");
    const double L = u1 - u0;
    const double slack = kKnotTolerance * L;
    if (a >= u0 - slack && b <= u1 + slack) return input.sub_surface(std::max(a, u0), std::min(b, u1), v0, v1);
    const NurbsSurface s = clamp_u(input);
    const double k = closure_ratio(s, tolerance);
    if (!(k > 0.0))
        throw InvalidInput("extend_closed_surface: the surface's boundary rows at u = " + format_value(u0) +
                           " and " + format_value(u1) + " differ by more than " + format_value(tolerance) +
                           "; the surface is not closed in this direction");
    // Copies c = first .. last cover [u0 + first L, u0 + (last + 1) L] ⊇ [a, b].
    const double first_copy = std::floor((a - u0 + slack) / L), last_copy = std::ceil((b - u0 - slack) / L) - 1;
    if (!(last_copy - first_copy + 1 <= kMaxPeriods) || !(std::abs(first_copy) <= kMaxPeriodsAway))
        throw InvalidInput("extend_closed_surface: range [" + format_value(a) + ", " + format_value(b) +
                           "] spans " + format_value(last_copy - first_copy + 1) + " periods of length " +
                           format_value(L) + " from " + format_value(first_copy) + " periods away; at most " +
                           std::to_string(kMaxPeriods) + " are joined, within " +
                           std::to_string(kMaxPeriodsAway) + " periods of the domain");
    const int first = clamped_int(first_copy, -kMaxPeriodsAway, kMaxPeriodsAway);
    const int last = first + clamped_int(last_copy - first_copy, 0, kMaxPeriods - 1);
    const int copies = last - first + 1;
    const int p = s.degree_u(), nu = s.count_u(), nv = s.count_v();
    const std::vector<double>& U = s.knots_u();
    // Knots: p+1 at the start, each copy's inner knots, p at each seam, p+1 at the end.
    std::vector<double> knots(static_cast<size_t>(p + 1), u0 + first * L);
    std::vector<Eigen::Vector3d> points;
    std::vector<double> weights;
    for (int c = first; c <= last; ++c) {
        const double shift = c * L;
        // Weights of copy c scaled by k^(c - first): its first row then carries the
        // previous copy's last-row weights, so the two rows are one.
        const double scale = std::pow(k, c - first);
        if (c > first) knots.insert(knots.end(), static_cast<size_t>(p), u0 + shift);
        for (size_t i = static_cast<size_t>(p + 1); i + static_cast<size_t>(p + 1) < U.size(); ++i)
            knots.push_back(U[i] + shift);
        for (int i = c > first ? 1 : 0; i < nu; ++i)
            for (int j = 0; j < nv; ++j) {
                points.push_back(s.point(i, j));
                weights.push_back(scale * s.weight(i, j));
            }
    }
    knots.insert(knots.end(), static_cast<size_t>(p + 1), u0 + (last + 1) * L);
    const int count = copies * (nu - 1) + 1;
    if (!s.is_rational() && k == 1.0) weights.clear();
    const NurbsSurface joined(p, s.degree_v(), std::move(knots), s.knots_v(), count, nv, std::move(points),
                              std::move(weights));
    return joined.sub_surface(a, b, v0, v1);
}

}  // namespace

bool is_closed_surface(const NurbsSurface& s, int direction, double tolerance) {
    const NurbsSurface t = clamp_u(direction == 0 ? s : s.swapped_uv());
    return closure_ratio(t, tolerance) > 0.0;
}

NurbsSurface extend_closed_surface(const NurbsSurface& s, int direction, double a, double b,
                                   double tolerance) {
    if (direction == 0) return extend_u(s, a, b, tolerance);
    return extend_u(s.swapped_uv(), a, b, tolerance).swapped_uv();
}

}  // namespace trimkit::geom
