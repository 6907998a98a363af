#include "geom/knot_insertion.h"

#include <cmath>
#include <string>

#include "geom/error.h"
#include "geom/knot_vector.h"

namespace trimkit::geom {
KnotInsertion plan_knot_insertion(const std::vector<double>& U, int p, double t, int times,
                                  const char* owner) {
    if (times < 0)
        throw InvalidInput(std::string(owner) + ": times = " + std::to_string(times) +
                           "; expected >= 0");
    const double a = U[p], b = U[U.size() - p - 1];
    if (!(t >= a && t <= b))
        throw InvalidInput(std::string(owner) + ": t = " + format_value(t) + " outside the domain [" +
                           format_value(a) + ", " + format_value(b) + "]");
    t = snap_to_knot(U, t, kKnotTolerance * (b - a));
    KnotInsertion plan;
    plan.p = p;
    plan.s = static_cast<int>(std::count(U.begin(), U.end(), t));
    plan.r = std::max(0, std::min(times, p - plan.s));
    if (plan.r == 0) return plan;
    // U[k] <= t < U[k+1]; t < U[m] here, since t == U[m] would mean s >= p + 1.
    plan.k = static_cast<int>(std::upper_bound(U.begin(), U.end(), t) - U.begin()) - 1;
    const int k = plan.k, s = plan.s;
    plan.alpha.assign(static_cast<size_t>(plan.r) * (p + 1), 0.0);
    for (int j = 1; j <= plan.r; ++j) {
        const int L = k - p + j;
        for (int i = 0; i <= p - j - s; ++i)
            plan.alpha[static_cast<size_t>(j - 1) * (p + 1) + i] = (t - U[L + i]) / (U[i + k + 1] - U[L + i]);
    }
    plan.knots.reserve(U.size() + plan.r);
    plan.knots.insert(plan.knots.end(), U.begin(), U.begin() + k + 1);
    plan.knots.insert(plan.knots.end(), plan.r, t);
    plan.knots.insert(plan.knots.end(), U.begin() + k + 1, U.end());
    return plan;
}

DomainClamp plan_domain_clamp(const std::vector<double>& U, int p, const char* owner) {
    DomainClamp clamp;
    std::vector<double> knots = U;
    const double a = U[p], b = U[U.size() - p - 1];
    for (double end : {a, b}) {
        KnotInsertion plan = plan_knot_insertion(knots, p, end, p, owner);
        if (plan.r == 0) continue;
        knots = plan.knots;
        clamp.insertions.push_back(std::move(plan));
    }
    const int la = static_cast<int>(std::upper_bound(knots.begin(), knots.end(), a) - knots.begin()) - 1;
    const int fb = static_cast<int>(std::lower_bound(knots.begin(), knots.end(), b) - knots.begin());
    clamp.first = la - p;
    clamp.end = fb;
    clamp.knots.assign(p + 1, a);
    clamp.knots.insert(clamp.knots.end(), knots.begin() + la + 1, knots.begin() + fb);
    clamp.knots.insert(clamp.knots.end(), p + 1, b);
    for (double x : clamp.knots)
        if (clamp.breaks.empty() || x != clamp.breaks.back()) clamp.breaks.push_back(x);
    return clamp;
}

}  // namespace trimkit::geom
