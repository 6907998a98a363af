#include "mesh/triangulate_polygon.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace trimkit::mesh {
namespace {

// Twice the signed area of (a, b, c): > 0 for a left turn.
double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
    return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

// Areas below this fraction of the squared polygon size count as zero (double
// rounding in the cross products of (u,v) points is about 1e-16 of it).
constexpr double kRelativeAreaEpsilon = 1e-14;
// A hole vertex this close to an outer vertex (relative to the ring's box) touches it:
// far above the rounding of loops meeting at one point, far below any trim segment.
constexpr double kTouchingRelative = 1e-10;

std::vector<int> without_duplicates(const std::vector<int>& ring) {
    std::vector<int> out;
    out.reserve(ring.size());
    for (int v : ring)
        if (out.empty() || out.back() != v) out.push_back(v);
    while (out.size() > 1 && out.front() == out.back()) out.pop_back();
    return out;
}

// A hole that touches `outer` at a vertex P (a circle tangent inside another, both
// loops through P; the two copies of P may differ by rounding, up to `snap`) needs no
// bridge: the ring runs to P, around the hole and back to the same P, and on. A bridge
// elsewhere would leave the ring pinched at P twice, and ear clipping could then fold
// a triangle over the pinch. Outer vertices are searched by u (sorted), so this is
// O((n + m) log n).
bool splice_touching_hole(const std::vector<Eigen::Vector2d>& uv, std::vector<int>& outer,
                          const std::vector<int>& hole, double snap) {
    std::vector<std::pair<double, size_t>> by_u;
    by_u.reserve(outer.size());
    for (size_t p = 0; p < outer.size(); ++p) by_u.emplace_back(uv[outer[p]].x(), p);
    std::sort(by_u.begin(), by_u.end());
    for (size_t q = 0; q < hole.size(); ++q) {
        const Eigen::Vector2d& h = uv[hole[q]];
        auto it = std::lower_bound(by_u.begin(), by_u.end(), std::make_pair(h.x() - snap, size_t{0}));
        for (; it != by_u.end() && it->first <= h.x() + snap; ++it) {
            const size_t p = it->second;
            if ((uv[outer[p]] - h).norm() > snap) continue;
            std::vector<int> merged(outer.begin(), outer.begin() + p + 1);
            for (size_t k = 1; k < hole.size(); ++k) merged.push_back(hole[(q + k) % hole.size()]);
            merged.insert(merged.end(), outer.begin() + p, outer.end());  // P once more
            outer = std::move(merged);
            return true;
        }
    }
    return false;
}

// True when M lies in the interior wedge at ring[p] (between the edge from the
// previous vertex and the edge to the next; the interior is on the left of a
// counter-clockwise ring).
bool wedge_contains(const std::vector<Eigen::Vector2d>& uv, const std::vector<int>& ring, size_t p,
                    const Eigen::Vector2d& M) {
    const size_t n = ring.size();
    const Eigen::Vector2d& a = uv[ring[(p + n - 1) % n]];
    const Eigen::Vector2d& P = uv[ring[p]];
    const Eigen::Vector2d& b = uv[ring[(p + 1) % n]];
    const bool left_of_in = cross(a, P, M) >= 0.0, left_of_out = cross(P, b, M) >= 0.0;
    return cross(a, P, b) >= 0.0 ? left_of_in && left_of_out : left_of_in || left_of_out;
}

// Among the copies of ring[p]'s point in the ring (a vertex an earlier bridge
// duplicated), the one whose wedge holds M: bridging to another copy would cross
// the earlier bridge (the ring is only weakly simple).
size_t copy_facing(const std::vector<Eigen::Vector2d>& uv, const std::vector<int>& ring, size_t p,
                   const Eigen::Vector2d& M) {
    if (wedge_contains(uv, ring, p, M)) return p;
    for (size_t k = 0; k < ring.size(); ++k)
        if (k != p && uv[ring[k]] == uv[ring[p]] && wedge_contains(uv, ring, k, M)) return k;
    return p;
}

// Joins `hole` (clockwise) into `outer` (counter-clockwise) by a bridge from the
// hole's rightmost vertex M to a vertex of `outer` visible from it. [Eberly,
// "Triangulation by ear clipping", Sec. 3]. Departure: a bridge vertex that earlier
// bridges duplicated is taken in the copy whose wedge faces M (copy_facing).
void bridge_hole(const std::vector<Eigen::Vector2d>& uv, std::vector<int>& outer,
                 const std::vector<int>& hole, double snap) {
    if (splice_touching_hole(uv, outer, hole, snap)) return;
    size_t m = 0;
    for (size_t k = 1; k < hole.size(); ++k) {
        const Eigen::Vector2d& a = uv[hole[k]];
        const Eigen::Vector2d& b = uv[hole[m]];
        if (a.x() > b.x() || (a.x() == b.x() && a.y() > b.y())) m = k;
    }
    const Eigen::Vector2d M = uv[hole[m]];
    // Closest edge hit by the ray M + s (1, 0), s >= 0.
    double best_x = std::numeric_limits<double>::infinity();
    size_t best_edge = outer.size();
    for (size_t k = 0; k < outer.size(); ++k) {
        const Eigen::Vector2d& a = uv[outer[k]];
        const Eigen::Vector2d& b = uv[outer[(k + 1) % outer.size()]];
        if ((a.y() > M.y()) == (b.y() > M.y()) && a.y() != M.y() && b.y() != M.y()) continue;
        double x;
        if (a.y() == b.y()) {
            if (a.y() != M.y()) continue;
            x = std::min(a.x(), b.x());
            if (x < M.x()) x = std::max(a.x(), b.x());
        } else {
            if ((a.y() - M.y()) * (b.y() - M.y()) > 0.0) continue;
            x = a.x() + (M.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
        }
        if (x >= M.x() && x < best_x) best_x = x, best_edge = k;
    }
    size_t p = 0;
    if (best_edge == outer.size()) {
        // No edge to the right (hole touching or outside the ring): nearest vertex.
        double best = std::numeric_limits<double>::infinity();
        for (size_t k = 0; k < outer.size(); ++k) {
            const double d = (uv[outer[k]] - M).squaredNorm();
            if (d < best) best = d, p = k;
        }
    } else {
        const size_t k0 = best_edge, k1 = (best_edge + 1) % outer.size();
        p = uv[outer[k0]].x() > uv[outer[k1]].x() ? k0 : k1;
        const Eigen::Vector2d I(best_x, M.y());
        const Eigen::Vector2d P = uv[outer[p]];
        if (P != I) {
            // A reflex vertex inside triangle (M, I, P) may hide P; take the one with
            // the smallest angle to the ray (then the closest).
            const double orient = cross(M, I, P);
            double best_tan = std::numeric_limits<double>::infinity(), best_d = best_tan;
            for (size_t k = 0; k < outer.size(); ++k) {
                const Eigen::Vector2d& R = uv[outer[k]];
                const Eigen::Vector2d& prev = uv[outer[(k + outer.size() - 1) % outer.size()]];
                const Eigen::Vector2d& next = uv[outer[(k + 1) % outer.size()]];
                if (k == p || cross(prev, R, next) > 0.0) continue;  // convex
                const double c1 = cross(M, I, R), c2 = cross(I, P, R), c3 = cross(P, M, R);
                const bool in = orient > 0 ? (c1 >= 0 && c2 >= 0 && c3 >= 0)
                                           : (c1 <= 0 && c2 <= 0 && c3 <= 0);
                if (!in || R.x() < M.x()) continue;
                const double tan = std::abs(R.y() - M.y()) / std::max(R.x() - M.x(), 1e-300);
                const double d = (R - M).squaredNorm();
                if (tan < best_tan || (tan == best_tan && d < best_d)) best_tan = tan, best_d = d, p = k;
            }
        }
    }
    p = copy_facing(uv, outer, p, M);
    std::vector<int> merged;
    merged.reserve(outer.size() + hole.size() + 2);
    merged.insert(merged.end(), outer.begin(), outer.begin() + p + 1);
    for (size_t k = 0; k <= hole.size(); ++k) merged.push_back(hole[(m + k) % hole.size()]);
    merged.insert(merged.end(), outer.begin() + p, outer.end());
    outer = std::move(merged);
}

void clip_convex(const std::vector<Eigen::Vector2d>& uv, const std::vector<int>& ring,
                 std::vector<std::array<int, 3>>& out) {
    // Clip strictly convex corners; collinear side points become vertices of later
    // triangles. [Balazs] Sec. 7 (departure: corner clipping instead of the paper's
    // upper-left zig-zag, which makes the same kind of fan without the search). A
    // corner is clipped only if at least 3 corners remain, so the last triangle is
    // not flat (a triangle with points on one side needs its opposite corner kept).
    const int n = static_cast<int>(ring.size());
    std::vector<int> prev(n), next(n);
    for (int k = 0; k < n; ++k) prev[k] = (k + n - 1) % n, next[k] = (k + 1) % n;
    auto turn = [&](int a, int b, int c) { return cross(uv[ring[a]], uv[ring[b]], uv[ring[c]]) > 0.0; };
    int corners = 0;
    for (int k = 0; k < n; ++k) corners += turn(prev[k], k, next[k]);
    int remaining = n, k = 0, since_clip = 0;
    while (remaining > 3) {
        const int a = prev[k], c = next[k];
        bool clip = false;
        int after = corners;
        if (turn(a, k, c)) {
            after = corners - 1 - turn(prev[a], a, k) - turn(k, c, next[c]) + turn(prev[a], a, c) +
                    turn(a, c, next[c]);
            clip = after >= 3 || since_clip > remaining;
        } else if (since_clip > 2 * remaining) {
            clip = true;  // all collinear: a flat triangle keeps the vertices connected
            after = corners;
        }
        if (!clip) {
            k = c;
            ++since_clip;
            continue;
        }
        out.push_back({ring[a], ring[k], ring[c]});
        next[a] = c;
        prev[c] = a;
        --remaining;
        corners = after;
        since_clip = 0;
        k = c;
    }
    out.push_back({ring[prev[k]], ring[k], ring[next[k]]});
}

void clip_ears(const std::vector<Eigen::Vector2d>& uv, const std::vector<int>& ring,
               std::vector<std::array<int, 3>>& out, Deadline* deadline) {
    const int n = static_cast<int>(ring.size());
    Eigen::AlignedBox2d box;
    for (int v : ring) box.extend(uv[v]);
    const double eps = kRelativeAreaEpsilon * box.sizes().squaredNorm();
    std::vector<int> prev(n), next(n);
    for (int k = 0; k < n; ++k) prev[k] = (k + n - 1) % n, next[k] = (k + 1) % n;
    auto at = [&](int k) -> const Eigen::Vector2d& { return uv[ring[k]]; };
    auto is_ear = [&](int k) {
        const int a = prev[k], c = next[k];
        const Eigen::Vector2d &A = at(a), &B = at(k), &C = at(c);
        if (cross(A, B, C) <= eps) return false;
        for (int j = next[c]; j != a; j = next[j]) {
            check_deadline(deadline, "triangulation");
            const Eigen::Vector2d& P = at(j);
            if (P == A || P == B || P == C) continue;  // duplicated (bridge) vertex
            // Only reflex or flat vertices can lie inside an ear of a simple polygon.
            if (cross(at(prev[j]), P, at(next[j])) > eps) continue;
            if (cross(A, B, P) >= 0 && cross(B, C, P) >= 0 && cross(C, A, P) >= 0) return false;
        }
        return true;
    };
    int remaining = n, k = 0, since_clip = 0;
    auto clip = [&](int v) {
        out.push_back({ring[prev[v]], ring[v], ring[next[v]]});
        next[prev[v]] = next[v];
        prev[next[v]] = prev[v];
        --remaining;
        since_clip = 0;
        return next[v];
    };
    while (remaining > 3) {
        if (is_ear(k)) {
            k = clip(k);
            continue;
        }
        k = next[k];
        if (++since_clip <= remaining) continue;
        // No proper ear: a flat vertex first (zero-area triangle, keeps it connected),
        // else the most convex vertex, else the least reflex one.
        int flat = -1, convex = -1, least = k;
        double best_convex = eps, best_least = -std::numeric_limits<double>::infinity();
        int j = k;
        for (int step = 0; step < remaining; ++step, j = next[j]) {
            const double c = cross(at(prev[j]), at(j), at(next[j]));
            if (std::abs(c) <= eps && flat < 0) flat = j;
            if (c > best_convex) best_convex = c, convex = j;
            if (c > best_least) best_least = c, least = j;
        }
        k = clip(flat >= 0 ? flat : convex >= 0 ? convex : least);
    }
    if (remaining == 3) out.push_back({ring[prev[k]], ring[k], ring[next[k]]});
}

}  // namespace

bool is_convex(const std::vector<Eigen::Vector2d>& uv, const std::vector<int>& ring) {
    const size_t n = ring.size();
    for (size_t k = 0; k < n; ++k)
        if (cross(uv[ring[(k + n - 1) % n]], uv[ring[k]], uv[ring[(k + 1) % n]]) < 0.0) return false;
    return true;
}

std::vector<std::array<int, 3>> triangulate_polygon(const std::vector<Eigen::Vector2d>& uv,
                                                    const std::vector<int>& outer,
                                                    const std::vector<std::vector<int>>& holes,
                                                    Deadline* deadline) {
    std::vector<std::array<int, 3>> triangles;
    std::vector<int> ring = without_duplicates(outer);
    if (ring.size() < 3) return triangles;
    std::vector<std::vector<int>> clean;
    for (const auto& hole : holes) {
        std::vector<int> h = without_duplicates(hole);
        if (h.size() >= 3) clean.push_back(std::move(h));
    }
    if (clean.empty() && is_convex(uv, ring)) {
        clip_convex(uv, ring, triangles);
        return triangles;
    }
    // Rightmost holes first, so later bridges cannot cross earlier ones.
    auto max_u = [&](const std::vector<int>& h) {
        double x = -std::numeric_limits<double>::infinity();
        for (int v : h) x = std::max(x, uv[v].x());
        return x;
    };
    std::sort(clean.begin(), clean.end(),
              [&](const auto& a, const auto& b) { return max_u(a) > max_u(b); });
    Eigen::AlignedBox2d box;
    for (int v : ring) box.extend(uv[v]);
    const double snap = kTouchingRelative * box.diagonal().norm();
    for (const auto& hole : clean) {
        check_deadline(deadline, "triangulation");
        bridge_hole(uv, ring, hole, snap);
    }
    clip_ears(uv, ring, triangles, deadline);
    return triangles;
}

}  // namespace trimkit::mesh
