#include "io/closed_surface_loops.h"
#include "io/trim_loop_repair.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <Eigen/Geometry>

#include "geom/analytic_curves.h"
#include "geom/extend_closed_surface.h"
#include "geom/surface_projector.h"

namespace trimkit::io {
namespace {

// Samples per Bézier span of a coedge (and at least this many per coedge) for
// the loops' range: a quadratic span's extreme between samples is ~1/256 of its
// bulge off, far inside kCoverPadding of a period for trims near a seam.
constexpr int kRangeSamples = 16;
// settle_winding: samples of an iso-curve over one period (its length to ~0.1%
// for a circle), and how much shorter another joint's iso-curve must be to take
// the gap from the closing joint (ties keep the loop as the file has it).
constexpr int kIsoSamples = 64;
constexpr double kShorterIso = 0.5;
// close_loop_along_its_pole: ends on one iso-line within this share of the domain
// (sw2022's pole at u = 1.1e-8 of [0, pi]), and turns this close to whole ones.
constexpr double kSameIsoLine = 1e-6;

std::pair<double, double> domain(const geom::NurbsSurface& s, int d) {
    return d == 0 ? s.domain_u() : s.domain_v();
}

void extend_by_samples(const geom::NurbsCurve2d& c, Eigen::AlignedBox2d* box) {
    const auto [a, b] = c.domain();
    int spans = 0;
    const std::vector<double>& U = c.knots();
    for (std::size_t i = 1; i < U.size(); ++i)
        if (U[i] > U[i - 1] && U[i] > a && U[i - 1] < b) ++spans;
    const int n = kRangeSamples * std::max(1, spans);
    for (int k = 0; k <= n; ++k) box->extend(c.evaluate(a + (b - a) * k / n));
}

Eigen::Vector2d loop_start(const geom::Loop& loop, std::size_t k) {
    const geom::NurbsCurve2d& c = loop.coedges[k].curve;
    return c.evaluate(c.domain().first);
}

Eigen::Vector2d loop_end(const geom::Loop& loop) {
    const geom::NurbsCurve2d& c = loop.coedges.back().curve;
    return c.evaluate(c.domain().second);
}

// The loops that wind around in direction d (period L), by index.
std::vector<std::size_t> winding_loops(const std::vector<geom::Loop>& loops, int d, double L) {
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < loops.size(); ++i)
        if (winding(loops[i], d, L) != 0) out.push_back(i);
    return out;
}

}  // namespace

int winding(const geom::Loop& loop, int d, double period) {
    if (loop.coedges.empty()) return 0;
    return static_cast<int>(std::lround((loop_end(loop)[d] - loop_start(loop, 0)[d]) / period));
}

SurfacePeriods closed_periods(const geom::NurbsSurface& s, double tolerance) {
    SurfacePeriods p;
    if (geom::is_closed_surface(s, 0, tolerance)) p.u = s.domain_u().second - s.domain_u().first;
    if (geom::is_closed_surface(s, 1, tolerance)) p.v = s.domain_v().second - s.domain_v().first;
    return p;
}

Eigen::Vector2d wrap_into_domain(const geom::NurbsSurface& s, const SurfacePeriods& periods,
                                 Eigen::Vector2d uv) {
    for (int d = 0; d < 2; ++d) {
        const auto [a, b] = domain(s, d);
        if (periods[d] > 0.0 && (uv[d] < a || uv[d] > b)) {
            double r = std::fmod(uv[d] - a, periods[d]);
            if (r < 0.0) r += periods[d];
            uv[d] = a + r;
        }
        uv[d] = std::clamp(uv[d], a, b);
    }
    return uv;
}

// Share of a period within which a curve's middle counts as near the seam.
constexpr double kNearSeam = 1e-3;

// How far c's middle lies from the seams of the closed directions (their sides,
// modulo the period), as a share of the period; 0.5 where none is closed.
double seam_clearance(const geom::NurbsCurve2d& c, const geom::NurbsSurface& surface,
                      const SurfacePeriods& periods) {
    const Eigen::Vector2d mid = wrap_into_domain(surface, periods, c.evaluate(0.5 * (c.domain().first + c.domain().second)));
    double clearance = 0.5;
    for (int d = 0; d < 2; ++d) {
        if (!(periods[d] > 0.0)) continue;
        const double a = domain(surface, d).first;
        const double x = (mid[d] - a) / periods[d];
        clearance = std::min({clearance, std::fabs(x), std::fabs(1.0 - x)});
    }
    return clearance;
}

// The coedge the others are shifted to continue: the first, unless its middle lies
// by a seam, where its side is a guess (sewn_patchwork.stp of bench/occt_reference's
// corpus: a sphere octant's meridian 3e-5 off its seam), then the one farthest from
// the seams.
std::size_t unwrap_anchor(const geom::Loop& loop, const geom::NurbsSurface& surface, const SurfacePeriods& periods) {
    if (loop.coedges.empty() || seam_clearance(loop.coedges[0].curve, surface, periods) >= kNearSeam) return 0;
    std::size_t best = 0;
    double best_clearance = -1.0;
    for (std::size_t k = 0; k < loop.coedges.size(); ++k) {
        const double c = seam_clearance(loop.coedges[k].curve, surface, periods);
        if (c > best_clearance) best = k, best_clearance = c;
    }
    return best;
}

bool unwrap_loop(geom::Loop& loop, const geom::NurbsSurface& surface, const SurfacePeriods& periods) {
    if (!periods.any()) return false;
    const double size = surface.control_box().diagonal().norm();
    const std::size_t n = loop.coedges.size(), anchor = unwrap_anchor(loop, surface, periods);
    if (anchor != 0)  // the loop starts at its anchor (a cycle: the order is the same)
        std::rotate(loop.coedges.begin(), loop.coedges.begin() + static_cast<long>(anchor), loop.coedges.end());
    // The whole periods moving `from` onto `joint` in the closed directions whose
    // parameter is not free there (0 where it is: a pole); `free` set when one is.
    const auto shift_onto = [&](const Eigen::Vector2d& joint, const Eigen::Vector2d& from, bool* free) {
        const Eigen::Vector2d at = wrap_into_domain(surface, periods, joint);
        Eigen::Vector2d shift = Eigen::Vector2d::Zero();
        for (int d = 0; d < 2; ++d) {
            if (!(periods[d] > 0.0)) continue;
            if (geom::parameter_is_free(surface, at, d, size)) {
                if (free) *free = true;
                continue;
            }
            shift[d] = periods[d] * std::round((joint[d] - from[d]) / periods[d]);
        }
        return shift;
    };
    const auto end_of = [&](std::size_t k) { return loop.coedges[k].curve.evaluate(loop.coedges[k].curve.domain().second); };
    const auto start_of = [&](std::size_t k) { return loop.coedges[k].curve.evaluate(loop.coedges[k].curve.domain().first); };
    bool moved = false;
    const auto move = [&](std::size_t k, const Eigen::Vector2d& shift) {
        if (shift.isZero()) return;
        geom::NurbsCurve2d& c = loop.coedges[k].curve;
        c = c.translated(shift);
        moved = true;
    };
    std::size_t first_free = n;  // the first coedge that starts where a parameter is free
    for (std::size_t k = 1; k < n; ++k) {
        bool free = false;
        move(k, shift_onto(end_of(k - 1), start_of(k), &free));
        if (free && first_free == n) first_free = k;
    }
    // The coedges after a pole are placed from there only by the one that leaves it,
    // whose side is a guess: they are placed back from the loop's start instead, across
    // joints where no parameter is free (sewn_patchwork.stp: a sphere octant whose
    // meridian from the pole ends by the seam, where the loop goes on).
    for (std::size_t k = n; k-- > first_free;) {
        bool free = false;
        const Eigen::Vector2d shift = shift_onto(start_of((k + 1) % n), end_of(k), &free);
        if (free) break;
        move(k, shift);
    }
    return moved;
}

double settle_winding(geom::Loop& loop, const geom::NurbsSurface& surface, const SurfacePeriods& periods) {
    const std::size_t n = loop.coedges.size();
    if (n < 2) return -1.0;
    double moved = -1.0;
    for (int d = 0; d < 2; ++d) {
        const double L = periods[d];
        if (!(L > 0.0)) continue;
        const double w = winding(loop, d, L);
        if (w == 0.0) continue;
        // Joint j lies between coedge j and j + 1 (j = n - 1: the loop's closing joint).
        auto iso_length = [&](std::size_t j) {
            const geom::NurbsCurve2d& c = loop.coedges[j].curve;
            const Eigen::Vector2d at = wrap_into_domain(surface, periods, c.evaluate(c.domain().second));
            const auto [a, b] = domain(surface, d);
            double length = 0.0;
            Eigen::Vector3d prev;
            for (int k = 0; k <= kIsoSamples; ++k) {
                Eigen::Vector2d uv = at;
                uv[d] = a + (b - a) * k / kIsoSamples;
                const Eigen::Vector3d x = surface.evaluate(uv.x(), uv.y());
                if (k > 0) length += (x - prev).norm();
                prev = x;
            }
            return length;
        };
        // A joint where the loop already steps by whole periods (across a pole, where
        // unwrap_loop leaves it) takes no second step: the two would cancel.
        auto steps = [&](std::size_t j) {
            const geom::NurbsCurve2d& a = loop.coedges[j].curve;
            const geom::NurbsCurve2d& b = loop.coedges[j + 1].curve;
            return std::round((b.evaluate(b.domain().first)[d] - a.evaluate(a.domain().second)[d]) / L) != 0.0;
        };
        std::size_t best = n - 1;
        double best_length = iso_length(n - 1);
        for (std::size_t j = 0; j + 1 < n; ++j) {
            if (steps(j)) continue;
            const double length = iso_length(j);
            if (length < kShorterIso * best_length) best = j, best_length = length;
        }
        if (best == n - 1) continue;
        Eigen::Vector2d shift = Eigen::Vector2d::Zero();
        shift[d] = -w * L;
        for (std::size_t k = best + 1; k < n; ++k)
            loop.coedges[k].curve = loop.coedges[k].curve.translated(shift);
        moved = best_length;
    }
    return moved;
}

namespace {

Eigen::AlignedBox2d loop_box(const geom::Loop& loop) {
    Eigen::AlignedBox2d box;
    for (const geom::Coedge& e : loop.coedges) extend_by_samples(e.curve, &box);
    return box;
}

void shift_loop(geom::Loop& loop, const Eigen::Vector2d& shift) {
    for (geom::Coedge& e : loop.coedges)
        e.curve = e.curve.translated(shift);
}

// Distance of a and b in d modulo the period.
double periodic_gap(double a, double b, double period) { return std::fabs(std::remainder(b - a, period)); }

// The loop made to start at coedge k: the coedges before it move to the end, shifted
// by the loop's winding so that they still continue the chain.
void start_loop_at(geom::Loop& loop, std::size_t k, const Eigen::Vector2d& winding_shift) {
    for (std::size_t j = 0; j < k; ++j)
        loop.coedges[j].curve = loop.coedges[j].curve.translated(winding_shift);
    std::rotate(loop.coedges.begin(), loop.coedges.begin() + static_cast<long>(k), loop.coedges.end());
}

geom::Coedge bridge(const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
    geom::Coedge e;
    e.curve = geom::line_segment(from, to, 0.0, 1.0);
    return e;
}

// One loop around the band between a (winding w = ±1 times in d) and b (winding -w):
// each started at the pair of their vertices closest in d (modulo L), b shifted by
// whole periods to face a's end, and two straight bridges across, a period apart.
geom::Loop band_loop(geom::Loop a, geom::Loop b, int d, double L, int w) {
    std::size_t ia = 0, ib = 0;
    double best = L;
    for (std::size_t i = 0; i < a.coedges.size(); ++i)
        for (std::size_t j = 0; j < b.coedges.size(); ++j) {
            const double g = periodic_gap(loop_start(a, i)[d], loop_start(b, j)[d], L);
            if (g < best - 1e-9 * L) best = g, ia = i, ib = j;
        }
    Eigen::Vector2d wrap = Eigen::Vector2d::Zero();
    wrap[d] = w * L;
    start_loop_at(a, ia, wrap);
    start_loop_at(b, ib, -wrap);
    Eigen::Vector2d shift = Eigen::Vector2d::Zero();
    shift[d] = L * std::round((loop_end(a)[d] - loop_start(b, 0)[d]) / L);
    shift_loop(b, shift);
    geom::Loop band;
    band.outer = true;
    band.coedges = std::move(a.coedges);
    band.coedges.push_back(bridge(loop_end(band), loop_start(b, 0)));
    const Eigen::Vector2d a_start = loop_start(band, 0);
    band.coedges.insert(band.coedges.end(), b.coedges.begin(), b.coedges.end());
    band.coedges.push_back(bridge(loop_end(band), a_start));
    return band;
}

}  // namespace

bool join_winding_loops(std::vector<geom::Loop>& loops, const SurfacePeriods& periods) {
    for (int d = 0; d < 2; ++d) {
        const double L = periods[d];
        if (!(L > 0.0)) continue;
        const std::vector<std::size_t> winders = winding_loops(loops, d, L);
        if (winders.size() != 2) continue;
        const std::size_t keep = winders[0], drop = winders[1];
        const int w = winding(loops[keep], d, L);
        if (std::abs(w) != 1 || winding(loops[drop], d, L) != -w) continue;
        loops[keep] = band_loop(std::move(loops[keep]), std::move(loops[drop]), d, L, w);
        loops.erase(loops.begin() + static_cast<long>(drop));
        for (std::size_t i = 0; i < loops.size(); ++i) loops[i].outer = i == keep;
        return true;
    }
    return false;
}

bool close_loop_along_its_pole(geom::Loop& loop, const geom::NurbsSurface& surface, const SurfacePeriods& periods) {
    if (loop.coedges.empty()) return false;
    const Eigen::Vector2d start = loop_start(loop, 0), end = loop_end(loop);
    const double size = surface.control_box().diagonal().norm();
    for (int d = 0; d < 2; ++d) {
        const int e = 1 - d;
        const double L = periods[d];
        if (!(L > 0.0)) continue;
        const auto [lo, hi] = domain(surface, e);
        const double turns = (end[d] - start[d]) / L;
        const bool same_line = std::abs(end[e] - start[e]) <= kSameIsoLine * (hi - lo);
        const bool whole_turns = std::abs(turns - std::round(turns)) <= kSameIsoLine;
        if (!same_line || whole_turns || !geom::parameter_is_free(surface, end, d, size)) continue;
        loop.coedges.push_back(bridge(end, start));
        return true;
    }
    return false;
}

bool close_winding_loop_at_pole(std::vector<geom::Loop>& loops, const geom::NurbsSurface& surface,
                                const SurfacePeriods& periods, bool reversed) {
    const double size = surface.control_box().diagonal().norm();
    const Eigen::Vector2d middle(0.5 * (surface.domain_u().first + surface.domain_u().second),
                                 0.5 * (surface.domain_v().first + surface.domain_v().second));
    for (int d = 0; d < 2; ++d) {
        const int e = 1 - d;
        const double L = periods[d];
        if (!(L > 0.0) || periods[e] > 0.0) continue;
        const std::vector<std::size_t> winders = winding_loops(loops, d, L);
        if (winders.size() != 1) continue;
        geom::Loop& loop = loops[winders[0]];
        const int w = winding(loop, d, L);
        if (std::abs(w) != 1) continue;
        const auto [lo, hi] = domain(surface, e);
        const auto pole_at = [&](double end) {
            Eigen::Vector2d at = middle;
            at[e] = end;
            return geom::parameter_is_free(surface, at, d, size);
        };
        const bool pole_lo = pole_at(lo), pole_hi = pole_at(hi);
        if (!pole_lo && !pole_hi) continue;
        // The face lies left of the loop in (u,v) (right on a reversed face): +v of a
        // loop along +u, -u of one along +v.
        const bool to_hi = pole_lo && pole_hi ? ((d == 0 ? w : -w) > 0) != reversed : pole_hi;
        const Eigen::Vector2d start = loop_start(loop, 0), end = loop_end(loop);
        Eigen::Vector2d end_at_pole = end, start_at_pole = start;
        end_at_pole[e] = start_at_pole[e] = to_hi ? hi : lo;
        loop.coedges.push_back(bridge(end, end_at_pole));
        loop.coedges.push_back(bridge(end_at_pole, start_at_pole));
        loop.coedges.push_back(bridge(start_at_pole, start));
        for (std::size_t i = 0; i < loops.size(); ++i) loops[i].outer = i == winders[0];
        return true;
    }
    return false;
}

namespace {

// The middle of the widest gap between the intervals on a circle of length L (from a),
// or nullopt when they cover it; the intervals' starts are taken modulo L.
std::optional<double> widest_gap_middle(std::vector<std::pair<double, double>> intervals, double a, double L) {
    for (auto& [lo, hi] : intervals) {
        const double start = a + std::fmod(std::fmod(lo - a, L) + L, L);
        hi = start + (hi - lo), lo = start;
    }
    std::sort(intervals.begin(), intervals.end());
    double best = 0.0, middle = a;
    double reach = -std::numeric_limits<double>::infinity();  // the farthest end, wrapped past a
    for (const auto& interval : intervals) reach = std::max(reach, interval.second - L);
    for (const auto& [lo, hi] : intervals) {
        if (lo - reach > best) best = lo - reach, middle = 0.5 * (lo + reach);
        reach = std::max(reach, hi);
    }
    if (!(best > 0.0)) return std::nullopt;
    return middle;
}

}  // namespace

bool place_natural_seam(std::vector<geom::Loop>& loops, const geom::NurbsSurface& surface,
                        const SurfacePeriods& periods) {
    if (loops.size() < 2) return false;
    double lo[2] = {surface.domain_u().first, surface.domain_v().first};
    double hi[2] = {surface.domain_u().second, surface.domain_v().second};
    bool moved = false;
    for (int d = 0; d < 2; ++d) {
        const double L = periods[d];
        if (!(L > 0.0)) continue;
        std::vector<std::pair<double, double>> ranges;
        bool crosses = false;
        for (std::size_t i = 1; i < loops.size(); ++i) {
            const Eigen::AlignedBox2d box = loop_box(loops[i]);
            ranges.emplace_back(box.min()[d], box.max()[d]);
            const double k = std::floor((box.max()[d] - lo[d]) / L);  // the seam below the box's top
            crosses |= box.min()[d] < lo[d] + (k - kOutsideDomain) * L;
        }
        double s = lo[d];
        if (crosses) {
            const std::optional<double> gap = widest_gap_middle(ranges, lo[d], L);
            if (!gap) continue;
            s = *gap;
        }
        for (std::size_t i = 1; i < loops.size(); ++i) {
            Eigen::Vector2d shift = Eigen::Vector2d::Zero();
            shift[d] = L * std::ceil((s - ranges[i - 1].first) / L - kOutsideDomain);
            shift_loop(loops[i], shift);
            moved |= shift[d] != 0.0;
        }
        moved |= s != lo[d];
        lo[d] = s, hi[d] = s + L;
    }
    if (moved) loops[0] = geom::rectangle_loop(lo[0], hi[0], lo[1], hi[1]);
    return moved;
}

bool place_loops_by_largest(std::vector<geom::Loop>& loops, const SurfacePeriods& periods) {
    if (!periods.any() || loops.size() < 2) return false;
    std::size_t largest = 0;
    for (std::size_t i = 1; i < loops.size(); ++i)
        if (std::fabs(signed_area(loops[i])) > std::fabs(signed_area(loops[largest]))) largest = i;
    const Eigen::AlignedBox2d range = loop_box(loops[largest]);
    bool moved = false;
    for (std::size_t i = 0; i < loops.size(); ++i) {
        if (i == largest || range.isEmpty()) continue;
        const Eigen::Vector2d centre = loop_box(loops[i]).center();
        Eigen::Vector2d shift = Eigen::Vector2d::Zero();
        for (int d = 0; d < 2; ++d) {
            const double L = periods[d], lo = range.min()[d], hi = range.max()[d];
            if (!(L > 0.0) || (centre[d] >= lo && centre[d] <= hi)) continue;
            const double k = std::round((0.5 * (lo + hi) - centre[d]) / L);
            if (centre[d] + k * L >= lo && centre[d] + k * L <= hi) shift[d] = k * L;
        }
        if (shift.isZero()) continue;
        shift_loop(loops[i], shift);
        moved = true;
    }
    return moved;
}

bool shift_loops_into_domain(std::vector<geom::Loop>& loops, const geom::NurbsSurface& surface,
                             const SurfacePeriods& periods) {
    if (!periods.any()) return false;
    Eigen::AlignedBox2d box;
    for (const geom::Loop& loop : loops) box.extend(loop_box(loop));
    if (box.isEmpty()) return false;
    Eigen::Vector2d shift = Eigen::Vector2d::Zero();
    for (int d = 0; d < 2; ++d) {
        const double L = periods[d];
        if (!(L > 0.0)) continue;
        const auto [a, b] = domain(surface, d);
        const double slack = kOutsideDomain * L;
        if (box.min()[d] >= a - slack && box.max()[d] <= b + slack) continue;
        const double k = std::round((0.5 * (a + b) - box.center()[d]) / L);
        if (box.min()[d] + k * L >= a - slack && box.max()[d] + k * L <= b + slack) shift[d] = k * L;
    }
    if (shift.isZero()) return false;
    for (geom::Loop& loop : loops) shift_loop(loop, shift);
    return true;
}

bool cover_loops(geom::NurbsSurface& surface, const std::vector<geom::Loop>& loops,
                 const SurfacePeriods& periods, double tolerance) {
    if (!periods.any()) return false;
    Eigen::AlignedBox2d box;
    for (const geom::Loop& loop : loops)
        for (const geom::Coedge& e : loop.coedges) extend_by_samples(e.curve, &box);
    if (box.isEmpty()) return false;
    bool changed = false;
    for (int d = 0; d < 2; ++d) {
        const double L = periods[d];
        if (!(L > 0.0)) continue;
        const auto [a, b] = domain(surface, d);
        const bool below = box.min()[d] < a - kOutsideDomain * L, above = box.max()[d] > b + kOutsideDomain * L;
        if (!below && !above) continue;
        const double lo = below ? box.min()[d] - kCoverPadding * L : a;
        const double hi = above ? box.max()[d] + kCoverPadding * L : b;
        if (hi - lo > geom::kMaxPeriods * L) continue;
        surface = geom::extend_closed_surface(surface, d, lo, hi, tolerance);
        changed = true;
    }
    return changed;
}

}  // namespace trimkit::io
