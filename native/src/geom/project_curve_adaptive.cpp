#include "geom/project_curve_adaptive.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <vector>

namespace trimkit::geom {
namespace {

struct Sample {
    double t;
    Eigen::Vector2d uv;  // unwrapped in the closed directions
};

// Re-projections count as nearer when they gain more than this fraction of the
// surface size (rounding of Newton's result is far below it).
constexpr double kSameDistance = 1e-12;

class Refiner {
public:
    Refiner(const SurfaceProjector& projector, const NurbsCurve3d& c, double tolerance, double pu, double pv)
        : projector_(projector), s_(projector.surface()), c_(c), tolerance_(tolerance) {
        period_[0] = pu;
        period_[1] = pv;
        start_[0] = s_.domain_u().first;
        start_[1] = s_.domain_v().first;
    }

    // (u,v) in the domain: closed directions taken modulo their period.
    Eigen::Vector2d wrapped(Eigen::Vector2d uv) const {
        for (int d = 0; d < 2; ++d)
            if (period_[d] > 0.0) uv[d] = start_[d] + positive_mod(uv[d] - start_[d], period_[d]);
        return uv;
    }

    // uv shifted by whole periods to lie nearest to `reference`.
    Eigen::Vector2d unwrapped(Eigen::Vector2d uv, const Eigen::Vector2d& reference) const {
        for (int d = 0; d < 2; ++d)
            if (period_[d] > 0.0) uv[d] += period_[d] * std::round((reference[d] - uv[d]) / period_[d]);
        return uv;
    }

    Eigen::Vector3d at(const Eigen::Vector2d& uv) const {
        const Eigen::Vector2d w = wrapped(uv);
        return s_.evaluate(w.x(), w.y());
    }

    // The foot point of x nearest to it among Newton runs started from each of
    // `nears` (SurfaceProjector::invert also starts from its grid), unwrapped to
    // lie nearest to the near it came from. Several starts matter where the
    // nearest point jumps between branches (a curve passing a cone's small end:
    // from the end circle's side, Newton stays clamped on the end circle).
    Eigen::Vector2d foot(const Eigen::Vector3d& x, std::initializer_list<Eigen::Vector2d> nears) const {
        Eigen::Vector2d best = *nears.begin();
        double best_d = std::numeric_limits<double>::infinity();
        for (const Eigen::Vector2d& n : nears) {
            const Eigen::Vector2d w = wrapped(n);
            const Eigen::Vector2d uv = unwrapped(projector_.invert(x, &w), n);
            const double d = (at(uv) - x).norm();
            if (d < best_d) best = uv, best_d = d;
        }
        return best;
    }

    double distance(const Sample& s) const { return (at(s.uv) - c_.evaluate(s.t)).norm(); }

    // Each sample re-projected from its neighbours (backwards, then forwards),
    // kept where that lies nearer to the curve: a wrong branch that
    // project_curve followed from the curve's start gives way to the right one.
    void settle_branches(std::vector<Sample>* samples) const {
        std::vector<Sample>& S = *samples;
        const double eps = kSameDistance * projector_.size();
        for (int pass = 0; pass < 2; ++pass)
            for (std::size_t step = 1; step < S.size(); ++step) {
                const std::size_t k = pass == 0 ? S.size() - 1 - step : step;
                const Sample& n = S[pass == 0 ? k + 1 : k - 1];
                const Sample candidate{S[k].t, foot(c_.evaluate(S[k].t), {n.uv})};
                if (distance(candidate) < distance(S[k]) - eps) S[k] = candidate;
            }
        for (std::size_t k = 1; k < S.size(); ++k) S[k].uv = unwrapped(S[k].uv, S[k - 1].uv);
    }

    // Appends the refined points strictly between a and b, then b.
    void refine(const Sample& a, const Sample& b, int depth, std::vector<Sample>* out) const {
        if (depth < kMaxBisectionDepth && static_cast<int>(out->size()) < kMaxProjectedPoints) {
            const double tm = 0.5 * (a.t + b.t);
            const Eigen::Vector2d mid = 0.5 * (a.uv + b.uv);
            const Eigen::Vector2d f = unwrapped(foot(c_.evaluate(tm), {mid, a.uv, b.uv}), mid);
            if ((at(mid) - at(f)).norm() > tolerance_) {
                const Sample m{tm, f};
                refine(a, m, depth + 1, out);
                refine(m, b, depth + 1, out);
                return;
            }
        }
        out->push_back(b);
    }

private:
    static double positive_mod(double x, double p) {
        const double r = std::fmod(x, p);
        return r < 0.0 ? r + p : r;
    }

    const SurfaceProjector& projector_;
    const NurbsSurface& s_;
    const NurbsCurve3d& c_;
    double tolerance_;
    double period_[2] = {0.0, 0.0};
    double start_[2] = {0.0, 0.0};
};

}  // namespace

NurbsCurve2d project_curve_adaptive(const SurfaceProjector& projector, const NurbsCurve3d& c,
                                    double tolerance, double period_u, double period_v,
                                    double* max_distance) {
    const NurbsCurve2d base = project_curve(projector, c, max_distance);
    if (base.degree() != 1) return base;
    const Refiner refiner(projector, c, tolerance, period_u, period_v);
    // Degree 1: point k sits at knot k + 1.
    const std::vector<double>& U = base.knots();
    const std::vector<Eigen::Vector2d>& P = base.points();
    std::vector<Sample> samples;
    samples.reserve(P.size());
    for (std::size_t k = 0; k < P.size(); ++k) {
        Eigen::Vector2d uv = P[k];
        if (k > 0) uv = refiner.unwrapped(uv, samples.back().uv);
        samples.push_back({U[k + 1], uv});
    }
    refiner.settle_branches(&samples);
    std::vector<Sample> refined{samples.front()};
    for (std::size_t k = 1; k < samples.size(); ++k) refiner.refine(samples[k - 1], samples[k], 0, &refined);
    std::vector<double> knots{refined.front().t};
    std::vector<Eigen::Vector2d> points;
    double worst = 0.0;
    for (const Sample& s : refined) {
        knots.push_back(s.t);
        points.push_back(s.uv);
        if (max_distance) worst = std::max(worst, (refiner.at(s.uv) - c.evaluate(s.t)).norm());
    }
    knots.push_back(refined.back().t);
    if (max_distance) *max_distance = worst;
    return NurbsCurve2d(1, std::move(knots), std::move(points));
}

}  // namespace trimkit::geom
