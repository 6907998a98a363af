#include "tess/trim_region.h"

#include <algorithm>
#include <cmath>

#include "geom/error.h"
#include "tess/surface_evaluator.h"

namespace trimkit::tess {
namespace {

// A coedge is never sampled with more points than this (a bound on memory for
// curves with thousands of spans).
constexpr int kMaxCoedgeSamples = 20000;
// Grid lines closer than this fraction of the range merge (knots repeated in a file).
constexpr double kLineMerge = 1e-12;

// Gauss-Legendre nodes on [-1, 1] and weights.
constexpr double kGauss2X[2] = {-0.5773502691896257, 0.5773502691896257};
constexpr double kGauss2W[2] = {1.0, 1.0};
constexpr double kGauss4X[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                0.8611363115940526};
constexpr double kGauss4W[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                0.3478548451374538};

// Distinct knot values of a curve inside its domain, both ends included.
std::vector<double> breaks(const std::vector<double>& U, double a, double b) {
    std::vector<double> t{a};
    for (double k : U)
        if (k > t.back() && k < b) t.push_back(k);
    t.push_back(b);
    return t;
}

// Sorted grid lines over [lo, hi]: the ends, `fixed` values inside, and each
// interval between them cut into pieces no longer than (hi - lo) / cells.
std::vector<double> grid_lines(double lo, double hi, std::vector<double> fixed, int cells) {
    const double range = hi - lo;
    fixed.push_back(lo);
    fixed.push_back(hi);
    std::sort(fixed.begin(), fixed.end());
    std::vector<double> base;
    for (double x : fixed) {
        if (x < lo || x > hi) continue;
        if (base.empty() || x - base.back() > kLineMerge * range) base.push_back(x);
    }
    base.back() = hi;
    std::vector<double> lines{base[0]};
    for (std::size_t k = 1; k < base.size(); ++k) {
        const double len = base[k] - base[k - 1];
        const int pieces = std::max(1, static_cast<int>(std::ceil(len / range * cells - 1e-9)));
        for (int i = 1; i <= pieces; ++i) lines.push_back(base[k - 1] + len * i / pieces);
    }
    return lines;
}

}  // namespace

TrimRegion::TrimRegion(const geom::Face& face, const TrimRegionOptions& options) {
    const auto [su0, su1] = face.surface.domain_u();
    const auto [sv0, sv1] = face.surface.domain_v();
    const int per_span = std::max(1, options.samples_per_span);
    for (const geom::Loop& loop : face.loops) {
        std::vector<Eigen::Vector2d> polygon;
        for (const geom::Coedge& coedge : loop.coedges) {
            const auto [a, b] = coedge.curve.domain();
            const std::vector<double> t = breaks(coedge.curve.knots(), a, b);
            const int spans = static_cast<int>(t.size()) - 1;
            const int per = std::clamp(per_span, (kMinCoedgeSamples + spans - 1) / spans,
                                       std::max(1, kMaxCoedgeSamples / spans));
            corners_.push_back(coedge.curve.evaluate(a));
            for (int s = 0; s < spans; ++s)
                for (int k = 0; k < per; ++k)
                    polygon.push_back(coedge.curve.evaluate(t[s] + (t[s + 1] - t[s]) * k / per));
        }
        if (polygon.size() >= 3) loops_.push_back(std::move(polygon));
    }
    if (loops_.empty())
        throw geom::InvalidInput("TrimRegion: face '" + face.name + "' has no loop with 3 or more points");

    for (const auto& loop : loops_)
        for (const auto& p : loop) box_.extend(p);
    box_ = box_.intersection(Eigen::AlignedBox2d(Eigen::Vector2d(su0, sv0), Eigen::Vector2d(su1, sv1)));
    if (box_.isEmpty())
        throw geom::InvalidInput("TrimRegion: the loops of face '" + face.name +
                                 "' lie outside the surface's domain");

    for (const auto& loop : loops_)
        for (std::size_t i = 0, n = loop.size(); i < n; ++i) segments_.push_back({loop[i], loop[(i + 1) % n]});
    Eigen::AlignedBox2d all;
    for (const auto& loop : loops_)
        for (const auto& p : loop) all.extend(p);
    const int bins = std::clamp(static_cast<int>(segments_.size() / 4), 1, 4096);
    bin_v0_ = all.min().y();
    bin_h_ = std::max(all.sizes().y(), 1e-300) / bins;
    bins_.resize(bins);
    for (int s = 0; s < static_cast<int>(segments_.size()); ++s) {
        const double lo = std::min(segments_[s].a.y(), segments_[s].b.y());
        const double hi = std::max(segments_[s].a.y(), segments_[s].b.y());
        const int b0 = std::clamp(static_cast<int>((lo - bin_v0_) / bin_h_), 0, bins - 1);
        const int b1 = std::clamp(static_cast<int>((hi - bin_v0_) / bin_h_), 0, bins - 1);
        for (int b = b0; b <= b1; ++b) bins_[b].push_back(s);
    }
}

std::vector<double> TrimRegion::crossings(double v) const {
    std::vector<double> u;
    const int bins = static_cast<int>(bins_.size());
    const double x = (v - bin_v0_) / bin_h_;
    if (!(x >= 0.0) || x > bins) return u;  // no segment reaches v (or v is NaN)
    const int b = std::min(static_cast<int>(x), bins - 1);
    for (int s : bins_[b]) {
        const Eigen::Vector2d& p = segments_[s].a;
        const Eigen::Vector2d& q = segments_[s].b;
        if ((p.y() > v) != (q.y() > v)) u.push_back(p.x() + (v - p.y()) * (q.x() - p.x()) / (q.y() - p.y()));
    }
    std::sort(u.begin(), u.end());
    return u;
}

bool TrimRegion::contains(const Eigen::Vector2d& uv) const {
    const std::vector<double> u = crossings(uv.y());
    const auto above = u.end() - std::upper_bound(u.begin(), u.end(), uv.x());
    return above % 2 == 1;
}

double trimmed_area(const geom::NurbsSurface& surface, const TrimRegion& region, int cells, int levels) {
    cells = std::max(1, cells);
    levels = std::clamp(levels, 0, 8);
    const Eigen::AlignedBox2d& box = region.box();
    std::vector<double> fu, fv;
    for (double k : surface.knots_u()) fu.push_back(k);
    for (double k : surface.knots_v()) fv.push_back(k);
    for (const auto& c : region.corners()) {
        fu.push_back(c.x());
        fv.push_back(c.y());
    }
    const std::vector<double> ul = grid_lines(box.min().x(), box.max().x(), fu, cells);
    const std::vector<double> vl = grid_lines(box.min().y(), box.max().y(), fv, cells);

    SurfaceEvaluator eval(surface);
    Eigen::Vector3d S, Su, Sv;
    // ∫ |Su × Sv| du along v = const over the inside intervals, weighted by w.
    const auto line = [&](double v) {
        const std::vector<double> x = region.crossings(v);
        double sum = 0.0;
        for (std::size_t k = 0; k + 1 < x.size(); k += 2) {
            const double a = std::max(x[k], ul.front()), b = std::min(x[k + 1], ul.back());
            if (!(b > a)) continue;
            // Pieces between grid lines, so each is smooth (knots are grid lines).
            auto it = std::upper_bound(ul.begin(), ul.end(), a);
            double lo = a;
            while (lo < b) {
                const double hi = (it != ul.end() && *it < b) ? *it++ : b;
                const double mid = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
                for (int g = 0; g < 4; ++g) {
                    eval.evaluate(mid + half * kGauss4X[g], v, S, Su, Sv);
                    sum += kGauss4W[g] * half * Su.cross(Sv).norm();
                }
                lo = hi;
            }
        }
        return sum;
    };

    // Rows a loop segment crosses (any segment with v-range overlapping the open row).
    std::vector<char> crossed(vl.size() - 1, 0);
    for (const auto& loop : region.loops())
        for (std::size_t i = 0, n = loop.size(); i < n; ++i) {
            const double lo = std::min(loop[i].y(), loop[(i + 1) % n].y());
            const double hi = std::max(loop[i].y(), loop[(i + 1) % n].y());
            if (!(hi > lo)) continue;
            auto first = std::upper_bound(vl.begin(), vl.end(), lo);
            const std::size_t r0 = first == vl.begin() ? 0 : first - vl.begin() - 1;
            for (std::size_t r = r0; r + 1 < vl.size() && vl[r] < hi; ++r) crossed[r] = 1;
        }

    double area = 0.0;
    const int sub = 1 << levels;
    for (std::size_t r = 0; r + 1 < vl.size(); ++r) {
        const double v0 = vl[r], v1 = vl[r + 1];
        if (!crossed[r]) {
            const double mid = 0.5 * (v0 + v1), half = 0.5 * (v1 - v0);
            for (int g = 0; g < 4; ++g) area += kGauss4W[g] * half * line(mid + half * kGauss4X[g]);
            continue;
        }
        for (int s = 0; s < sub; ++s) {
            const double a = v0 + (v1 - v0) * s / sub, b = v0 + (v1 - v0) * (s + 1) / sub;
            const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
            for (int g = 0; g < 2; ++g) area += kGauss2W[g] * half * line(mid + half * kGauss2X[g]);
        }
    }
    return area;
}

}  // namespace trimkit::tess
