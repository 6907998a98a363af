#include "geom/curve_interpolation.h"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "geom/bspline_basis.h"
#include "geom/error.h"
#include "geom/knot_vector.h"

namespace trimkit::geom {

template <int Dim>
std::vector<double> chord_length_parameters(const std::vector<Eigen::Matrix<double, Dim, 1>>& Q) {
    if (Q.size() < 2)
        throw InvalidInput("chord_length_parameters: " + std::to_string(Q.size()) +
                           " points; expected at least 2");
    std::vector<double> u(Q.size(), 0.0);
    for (size_t k = 1; k < Q.size(); ++k) {
        const double d = (Q[k] - Q[k - 1]).norm();
        if (!(d > 0))
            throw InvalidInput("chord_length_parameters: points " + std::to_string(k - 1) +
                               " and " + std::to_string(k) + " coincide");
        u[k] = u[k - 1] + d;
    }
    const double total = u.back();
    for (double& x : u) x /= total;
    u.back() = 1.0;
    return u;
}

template <int Dim>
NurbsCurve<Dim> interpolate_curve(const std::vector<Eigen::Matrix<double, Dim, 1>>& Q,
                                  int degree, std::vector<double> params) {
    const int n = static_cast<int>(Q.size()) - 1;
    if (n < 1)
        throw InvalidInput("interpolate_curve: " + std::to_string(Q.size()) +
                           " points; expected at least 2");
    if (degree < 1 || degree > kMaxDegree)
        throw InvalidInput("interpolate_curve: degree " + std::to_string(degree) +
                           "; expected 1 .. " + std::to_string(kMaxDegree));
    for (int k = 0; k <= n; ++k)
        if (!Q[k].allFinite())
            throw InvalidInput("interpolate_curve: point " + std::to_string(k) + " is not finite");
    if (params.empty()) params = chord_length_parameters(Q);
    if (static_cast<int>(params.size()) != n + 1)
        throw InvalidInput("interpolate_curve: " + std::to_string(params.size()) +
                           " parameters for " + std::to_string(n + 1) + " points");
    for (int k = 0; k <= n; ++k) {
        if (!std::isfinite(params[k]) || (k > 0 && !(params[k] > params[k - 1]))) {
            std::ostringstream msg;
            msg << "interpolate_curve: parameter " << k << " = " << params[k]
                << "; expected finite, strictly increasing values";
            throw InvalidInput(msg.str());
        }
    }
    const int p = std::min(degree, n);
    // Knots by averaging, [PT] Eq. 9.8.
    std::vector<double> U(n + p + 2);
    for (int j = 0; j <= p; ++j) {
        U[j] = params.front();
        U[n + 1 + j] = params.back();
    }
    for (int j = 1; j <= n - p; ++j) {
        double s = 0;
        for (int i = j; i <= j + p - 1; ++i) s += params[i];
        U[j + p] = s / p;
    }
    // N P = Q, row k holding N_{span-p..span, p}(ū_k); banded with p+1 entries per row.
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve((n + 1) * (p + 1));
    std::vector<double> N(p + 1);
    for (int k = 0; k <= n; ++k) {
        const int span = knot_span(U, p, params[k]);
        basis_functions(U, p, span, params[k], N.data());
        for (int j = 0; j <= p; ++j)
            if (N[j] != 0.0) entries.emplace_back(k, span - p + j, N[j]);
    }
    Eigen::SparseMatrix<double> A(n + 1, n + 1);
    A.setFromTriplets(entries.begin(), entries.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
    lu.compute(A);
    if (lu.info() != Eigen::Success)
        throw NumericalFailure("interpolate_curve: the interpolation matrix for " +
                               std::to_string(n + 1) + " points is singular");
    Eigen::Matrix<double, Eigen::Dynamic, Dim> rhs(n + 1, Dim);
    for (int k = 0; k <= n; ++k) rhs.row(k) = Q[k].transpose();
    const Eigen::Matrix<double, Eigen::Dynamic, Dim> X = lu.solve(rhs);
    if (lu.info() != Eigen::Success || !X.allFinite())
        throw NumericalFailure("interpolate_curve: solving for " + std::to_string(n + 1) +
                               " control points failed");
    std::vector<Eigen::Matrix<double, Dim, 1>> P(n + 1);
    for (int i = 0; i <= n; ++i) P[i] = X.row(i).transpose();
    P.front() = Q.front();  // exact end points, whatever the rounding
    P.back() = Q.back();
    return NurbsCurve<Dim>(p, std::move(U), std::move(P));
}

template std::vector<double> chord_length_parameters(const std::vector<Eigen::Vector2d>&);
template std::vector<double> chord_length_parameters(const std::vector<Eigen::Vector3d>&);
template NurbsCurve<2> interpolate_curve(const std::vector<Eigen::Vector2d>&, int,
                                         std::vector<double>);
template NurbsCurve<3> interpolate_curve(const std::vector<Eigen::Vector3d>&, int,
                                         std::vector<double>);

namespace {

// Initial knot spans per piece are cut into this many sample intervals.
constexpr int kIntervalsPerSpan = 4;
// Samples per knot span when looking for crossings of map breaks.
constexpr int kCrossingScan = 32;

// Parameters in (a, b) where c crosses the line coordinate[axis] == value.
void find_crossings(const NurbsCurve2d& c, const std::vector<double>& spans, int axis,
                    double value, std::vector<double>& out) {
    for (size_t s = 0; s + 1 < spans.size(); ++s) {
        const double a = spans[s], b = spans[s + 1];
        double t_prev = a, f_prev = c.evaluate(a)[axis] - value;
        for (int j = 1; j <= kCrossingScan; ++j) {
            const double t = a + (b - a) * j / kCrossingScan;
            const double f = c.evaluate(t)[axis] - value;
            if ((f_prev < 0 && f > 0) || (f_prev > 0 && f < 0)) {
                double lo = t_prev, hi = t, flo = f_prev;
                for (int it = 0; it < 200 && hi - lo > 0; ++it) {  // bisection to rounding
                    const double mid = 0.5 * (lo + hi);
                    if (mid <= lo || mid >= hi) break;
                    const double fm = c.evaluate(mid)[axis] - value;
                    if ((fm < 0) == (flo < 0)) {
                        lo = mid;
                        flo = fm;
                    } else {
                        hi = mid;
                    }
                }
                out.push_back(0.5 * (lo + hi));
            }
            t_prev = t;
            f_prev = f;
        }
    }
}

// Joins clamped cubic pieces on consecutive domains with a C0 knot (multiplicity p).
NurbsCurve2d join_pieces(const std::vector<NurbsCurve2d>& pieces) {
    const int p = pieces.front().degree();
    std::vector<double> U = pieces.front().knots();
    std::vector<Eigen::Vector2d> P = pieces.front().points();
    for (size_t k = 1; k < pieces.size(); ++k) {
        U.pop_back();
        const auto& V = pieces[k].knots();
        U.insert(U.end(), V.begin() + p + 1, V.end());
        P.insert(P.end(), pieces[k].points().begin() + 1, pieces[k].points().end());
    }
    return NurbsCurve2d(p, std::move(U), std::move(P));
}

}  // namespace

NurbsCurve2d refit_mapped_curve(const NurbsCurve2d& c,
                                std::function<Eigen::Vector2d(Eigen::Vector2d)> map,
                                double tolerance, const MapBreaks& breaks) {
    if (!(tolerance > 0) || !std::isfinite(tolerance)) {
        std::ostringstream msg;
        msg << "refit_mapped_curve: tolerance = " << tolerance << "; expected a finite value > 0";
        throw InvalidInput(msg.str());
    }
    const int p = c.degree();
    const auto [a, b] = c.domain();
    const std::vector<double> spans = distinct_knots(c.knots(), p);
    // Split points: knots where c is below C2, and crossings of the map's breaks.
    std::vector<double> cuts;
    for (size_t s = 1; s + 1 < spans.size(); ++s)
        if (knot_multiplicity(c.knots(), spans[s]) >= p - 1) cuts.push_back(spans[s]);
    for (double u : breaks.u) find_crossings(c, spans, 0, u, cuts);
    for (double v : breaks.v) find_crossings(c, spans, 1, v, cuts);
    const double min_gap = kKnotTolerance * (b - a);
    cuts.push_back(a);
    cuts.push_back(b);
    std::sort(cuts.begin(), cuts.end());
    std::vector<double> ends{a};
    for (double t : cuts)
        if (t - ends.back() > min_gap && b - t > min_gap) ends.push_back(t);
    ends.push_back(b);

    auto mapped = [&](double t) {
        const Eigen::Vector2d q = map(c.evaluate(t));
        if (!q.allFinite()) {
            std::ostringstream msg;
            msg << "refit_mapped_curve: the map gives a non-finite point at curve parameter " << t;
            throw NumericalFailure(msg.str());
        }
        return q;
    };

    // Initial samples: every piece's share of the knot spans, kIntervalsPerSpan each.
    std::vector<std::vector<double>> samples(ends.size() - 1);
    for (size_t k = 0; k + 1 < ends.size(); ++k) {
        std::vector<double> bounds{ends[k]};
        for (double s : spans)
            if (s > ends[k] + min_gap && s < ends[k + 1] - min_gap) bounds.push_back(s);
        bounds.push_back(ends[k + 1]);
        for (size_t s = 0; s + 1 < bounds.size(); ++s)
            for (int j = 0; j < kIntervalsPerSpan; ++j)
                samples[k].push_back(bounds[s] + (bounds[s + 1] - bounds[s]) * j / kIntervalsPerSpan);
        samples[k].push_back(ends[k + 1]);
    }

    std::vector<NurbsCurve2d> pieces;
    size_t total = 0;
    for (const auto& s : samples) total += s.size();
    for (auto& t : samples) {
        while (true) {
            std::vector<Eigen::Vector2d> Q;
            Q.reserve(t.size());
            for (double x : t) Q.push_back(mapped(x));
            const NurbsCurve2d fit = interpolate_curve<2>(Q, 3, t);
            std::vector<double> refined{t.front()};
            bool ok = true;
            for (size_t i = 0; i + 1 < t.size(); ++i) {
                const double mid = 0.5 * (t[i] + t[i + 1]);
                const double deviation = (fit.evaluate(mid) - mapped(mid)).norm();
                if (deviation >= tolerance) {
                    if (!(mid > t[i] && mid < t[i + 1])) {
                        std::ostringstream msg;
                        msg << "refit_mapped_curve: deviation " << deviation << " at curve parameter "
                            << mid << " stays above tolerance " << tolerance
                            << " down to the smallest interval (is the map discontinuous?)";
                        throw NumericalFailure(msg.str());
                    }
                    refined.push_back(mid);
                    ok = false;
                }
                refined.push_back(t[i + 1]);
            }
            if (ok) {
                pieces.push_back(fit);
                break;
            }
            total += refined.size() - t.size();
            if (total > static_cast<size_t>(kMaxRefitSamples)) {
                std::ostringstream msg;
                msg << "refit_mapped_curve: " << kMaxRefitSamples
                    << " samples do not bring the fit within tolerance " << tolerance;
                throw NumericalFailure(msg.str());
            }
            t = std::move(refined);
        }
    }
    return join_pieces(pieces);
}

}  // namespace trimkit::geom
