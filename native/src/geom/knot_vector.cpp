// Knot vector validation and queries (see knot_vector.h for the rules).
#include "geom/knot_vector.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "geom/bspline_basis.h"
#include "geom/error.h"

namespace trimkit::geom {

namespace {

[[noreturn]] void fail(const std::string& owner, const std::string& what) {
    throw InvalidInput(owner + ": " + what);
}

std::string knot_text(const std::vector<double>& U, size_t i) {
    return "knot[" + std::to_string(i) + "] = " + format_value(U[i]);
}

}  // namespace

void validate_knot_vector(const std::vector<double>& U, int p, int point_count,
                          const std::string& owner) {
    // Degree first, before anything whose size depends on it.
    if (p < 1 || p > kMaxDegree)
        fail(owner, "degree " + std::to_string(p) + "; expected 1.." +
                        std::to_string(kMaxDegree) + " (kMaxDegree)");
    if (point_count < p + 1)
        fail(owner, std::to_string(point_count) + " control points for degree " +
                        std::to_string(p) + "; expected at least degree + 1 = " +
                        std::to_string(p + 1));
    const size_t expected = static_cast<size_t>(point_count) + p + 1;
    if (U.size() != expected)
        fail(owner, std::to_string(U.size()) + " knots, expected " + std::to_string(expected) +
                        " (degree " + std::to_string(p) + ", " + std::to_string(point_count) +
                        " control points)");
    for (size_t i = 0; i < U.size(); ++i)
        if (!std::isfinite(U[i])) fail(owner, knot_text(U, i) + "; knots must be finite");
    for (size_t i = 1; i < U.size(); ++i)
        if (U[i] < U[i - 1])
            fail(owner, knot_text(U, i) + " < " + knot_text(U, i - 1) +
                            "; knots must be non-decreasing");
    // Exact multiplicity: evaluation only needs non-empty spans, and near-equal
    // knots are legal (if wasteful).
    for (size_t i = 0; i < U.size();) {
        size_t j = i;
        while (j + 1 < U.size() && U[j + 1] == U[i]) ++j;
        const size_t multiplicity = j - i + 1;
        if (multiplicity > static_cast<size_t>(p) + 1)
            fail(owner, "knot value " + format_value(U[i]) + " has multiplicity " +
                            std::to_string(multiplicity) + " (knot[" + std::to_string(i) +
                            "] .. knot[" + std::to_string(j) + "]); expected at most degree + 1 = " +
                            std::to_string(p + 1));
        i = j + 1;
    }
    const size_t n = static_cast<size_t>(point_count) - 1;
    if (!(U[p] < U[n + 1]))
        fail(owner, "empty domain: " + knot_text(U, p) + " == " + knot_text(U, n + 1) +
                        "; expected knot[p] < knot[n+1]");
}

std::vector<double> distinct_knots(const std::vector<double>& U, int p) {
    const int n = static_cast<int>(U.size()) - p - 2;
    const double a = U[p], b = U[n + 1];
    const double tol = kKnotTolerance * (b - a);
    std::vector<double> result{a};
    for (int i = p + 1; i <= n; ++i)
        if (U[i] - result.back() > tol && b - U[i] > tol) result.push_back(U[i]);
    result.push_back(b);
    return result;
}

bool is_clamped(const std::vector<double>& U, int p) {
    if (p < 0 || U.size() < 2 * static_cast<size_t>(p) + 2) return false;
    const size_t m = U.size() - 1;
    for (int i = 1; i <= p; ++i)
        if (U[i] != U[0] || U[m - i] != U[m]) return false;
    return true;
}

// Departure: the tolerance scales with the whole knot range U[0] .. U[m], since
// the degree (and so the domain) is not known here.
int knot_multiplicity(const std::vector<double>& U, double u) {
    if (U.empty()) return 0;
    const double tol = kKnotTolerance * (U.back() - U.front());
    int count = 0;
    for (double x : U)
        if (std::abs(x - u) <= tol) ++count;
    return count;
}

std::vector<double> uniform_clamped_knots(int point_count, int p, double a, double b) {
    if (p < 1 || p > kMaxDegree)
        throw InvalidInput("uniform_clamped_knots: degree " + std::to_string(p) +
                           "; expected 1.." + std::to_string(kMaxDegree));
    if (point_count < p + 1)
        throw InvalidInput("uniform_clamped_knots: " + std::to_string(point_count) +
                           " control points for degree " + std::to_string(p) +
                           "; expected at least " + std::to_string(p + 1));
    if (!(a < b) || !std::isfinite(a) || !std::isfinite(b))
        throw InvalidInput("uniform_clamped_knots: domain [" + format_value(a) + ", " +
                           format_value(b) + "]; expected finite a < b");
    const int n = point_count - 1;
    const int segments = n - p + 1;
    std::vector<double> U(static_cast<size_t>(point_count) + p + 1);
    for (int i = 0; i <= p; ++i) {
        U[i] = a;
        U[n + 1 + i] = b;
    }
    for (int i = 1; i < segments; ++i)
        U[p + i] = a + (b - a) * static_cast<double>(i) / segments;
    return U;
}

std::vector<double> bezier_knots(int p, double a, double b) {
    if (p < 0 || p > kMaxDegree)
        throw InvalidInput("bezier_knots: degree " + std::to_string(p) + "; expected 0.." +
                           std::to_string(kMaxDegree));
    std::vector<double> U(2 * static_cast<size_t>(p + 1), a);
    for (int i = p + 1; i < 2 * (p + 1); ++i) U[i] = b;
    return U;
}

double snap_to_knot(const std::vector<double>& U, double t, double tol) {
    auto it = std::lower_bound(U.begin(), U.end(), t);
    double best = t, dist = tol;
    if (it != U.end() && std::abs(*it - t) <= dist) { best = *it; dist = std::abs(*it - t); }
    if (it != U.begin() && std::abs(*(it - 1) - t) <= dist) best = *(it - 1);
    return best;
}

}  // namespace trimkit::geom
