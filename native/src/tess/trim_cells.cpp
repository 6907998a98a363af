#include "tess/trim_cells.h"
#include "geom/clamped_int.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <unordered_map>

namespace trimkit::tess {
namespace {

// Crossing points closer than this fraction of the cell's size to a corner are
// snapped onto it, so the two or four cells meeting there produce one vertex.
constexpr double kCornerSnap = 1e-12;
// Segment buckets per axis: about sqrt(#segments), within these limits.
constexpr int kMinBuckets = 1, kMaxBuckets = 512;

struct UvKey {
    std::uint64_t u, v;
    bool operator==(const UvKey& o) const { return u == o.u && v == o.v; }
};
struct UvKeyHash {
    size_t operator()(const UvKey& k) const { return k.u * 0x9E3779B97F4A7C15ull ^ (k.v + (k.u >> 7)); }
};
UvKey key_of(const Eigen::Vector2d& uv) {
    UvKey k;
    const double u = uv.x() == 0.0 ? 0.0 : uv.x(), v = uv.y() == 0.0 ? 0.0 : uv.y();  // -0 == 0
    std::memcpy(&k.u, &u, sizeof u);
    std::memcpy(&k.v, &v, sizeof v);
    return k;
}

// Vertices of the trimmed cells, one per (u,v).
class VertexTable {
public:
    // `crossing`: xyz is a crossing's (a trim point at the same (u,v) makes it a trim point).
    int add(const Eigen::Vector2d& uv, const Eigen::Vector3d* xyz, bool crossing = false) {
        auto [it, inserted] = index_.try_emplace(key_of(uv), static_cast<int>(vertices_.size()));
        if (inserted) {
            TrimmedVertex vertex;
            vertex.uv = uv;
            if (xyz) vertex.xyz = *xyz, vertex.on_trim = true, vertex.crossing = crossing;
            vertices_.push_back(vertex);
        } else if (xyz && !vertices_[it->second].on_trim) {
            vertices_[it->second].xyz = *xyz;  // trim points keep their given xyz
            vertices_[it->second].on_trim = true;
            vertices_[it->second].crossing = crossing;
        } else if (xyz && !crossing) {
            vertices_[it->second].crossing = false;
        }
        return it->second;
    }
    const Eigen::Vector2d& uv(int index) const { return vertices_[index].uv; }
    std::vector<TrimmedVertex> take() { return std::move(vertices_); }

private:
    std::unordered_map<UvKey, int, UvKeyHash> index_;
    std::vector<TrimmedVertex> vertices_;
};

// Uniform buckets over the grid's box holding the trim segments that overlap them.
class SegmentBuckets {
public:
    SegmentBuckets(const Eigen::AlignedBox2d& box, const std::vector<std::array<Eigen::Vector2d, 2>>& segments)
        : box_(box) {
        n_ = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(segments.size()))),
                        kMinBuckets, kMaxBuckets);
        buckets_.resize(static_cast<size_t>(n_) * n_);
        for (size_t s = 0; s < segments.size(); ++s) {
            const auto& [a, b] = segments[s];
            const int i0 = column(std::min(a.x(), b.x())), i1 = column(std::max(a.x(), b.x()));
            const int j0 = row(std::min(a.y(), b.y())), j1 = row(std::max(a.y(), b.y()));
            for (int i = i0; i <= i1; ++i)
                for (int j = j0; j <= j1; ++j) buckets_[i * n_ + j].push_back(static_cast<int>(s));
        }
    }
    int column(double u) const { return index(u, box_.min().x(), box_.max().x()); }
    int row(double v) const { return index(v, box_.min().y(), box_.max().y()); }
    int count() const { return n_; }
    const std::vector<int>& bucket(int i, int j) const { return buckets_[i * n_ + j]; }

private:
    int index(double x, double lo, double hi) const {
        const double f = (x - lo) / (hi - lo) * n_;
        return geom::clamped_int(std::floor(f), 0, n_ - 1);
    }
    Eigen::AlignedBox2d box_;
    int n_ = 1;
    std::vector<std::vector<int>> buckets_;
};

// Sides of a cell, counter-clockwise from (u0, v0); perimeter positions run 0..4,
// corner k at position k.
enum Side { kBottom = 0, kRight = 1, kTop = 2, kLeft = 3 };

double perimeter_position(const Cell& c, int side, const Eigen::Vector2d& p) {
    double pos = 0.0;
    switch (side) {
        case kBottom: pos = (p.x() - c.u0) / (c.u1 - c.u0); break;
        case kRight: pos = 1.0 + (p.y() - c.v0) / (c.v1 - c.v0); break;
        case kTop: pos = 2.0 + (c.u1 - p.x()) / (c.u1 - c.u0); break;
        default: pos = 3.0 + (c.v1 - p.y()) / (c.v1 - c.v0); break;
    }
    pos = std::clamp(pos, 0.0, 4.0);
    return pos >= 4.0 ? pos - 4.0 : pos;
}

double boundary_position(const Cell& c, const Eigen::Vector2d& p) {
    if (p.y() == c.v0 && p.x() < c.u1) return perimeter_position(c, kBottom, p);
    if (p.x() == c.u1 && p.y() < c.v1) return perimeter_position(c, kRight, p);
    if (p.y() == c.v1 && p.x() > c.u0) return perimeter_position(c, kTop, p);
    return perimeter_position(c, kLeft, p);
}

bool inside(const Cell& c, const Eigen::Vector2d& p) {
    return c.u0 <= p.x() && p.x() < c.u1 && c.v0 <= p.y() && p.y() < c.v1;
}

// The part of segment a + t (b - a), t in [0,1], inside the half-open cell:
// t in [lo, hi], entering through side lo_side and leaving through hi_side.
struct Clip {
    double lo = 0.0, hi = 1.0;
    int lo_side = -1, hi_side = -1;
};

Clip clip(const Cell& c, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    Clip r;
    auto axis = [&](double a_x, double b_x, double x0, double x1, int side0, int side1) {
        const double d = b_x - a_x;
        if (d == 0.0) {
            if (!(x0 <= a_x && a_x < x1)) r.lo = 2.0, r.hi = -1.0;  // empty
            return;
        }
        const double t0 = (x0 - a_x) / d, t1 = (x1 - a_x) / d;
        const double enter = d > 0 ? t0 : t1, leave = d > 0 ? t1 : t0;
        const int enter_side = d > 0 ? side0 : side1, leave_side = d > 0 ? side1 : side0;
        if (enter >= r.lo) r.lo = enter, r.lo_side = enter_side;
        if (leave <= r.hi) r.hi = leave, r.hi_side = leave_side;
    };
    axis(a.x(), b.x(), c.u0, c.u1, kLeft, kRight);
    axis(a.y(), b.y(), c.v0, c.v1, kBottom, kTop);
    return r;
}

// A crossing of a trim segment with a cell side.
struct Crossing {
    Eigen::Vector2d uv;
    Eigen::Vector3d xyz;
    double position = 0.0;  // on the cell's perimeter
    bool removable = false;  // strictly inside a segment remove_crossings may take it from
};

Crossing crossing(const Cell& c, const PolylinePoint& a, const PolylinePoint& b, int side) {
    // t from the side's line alone (the neighbouring cell computes the same value), and
    // the point's coordinate on that line set exactly to the line's value.
    Crossing x;
    double t = 0.0;
    const double line = side == kLeft ? c.u0 : side == kRight ? c.u1 : side == kBottom ? c.v0 : c.v1;
    if (side == kLeft || side == kRight)
        t = (line - a.uv.x()) / (b.uv.x() - a.uv.x());
    else
        t = (line - a.uv.y()) / (b.uv.y() - a.uv.y());
    if (t <= 0.0) {
        x.uv = a.uv, x.xyz = a.xyz;
    } else if (t >= 1.0) {
        x.uv = b.uv, x.xyz = b.xyz;
    } else {
        x.uv = a.uv + t * (b.uv - a.uv);
        x.xyz = a.xyz + t * (b.xyz - a.xyz);
        x.removable = !a.keep_crossings && !b.keep_crossings;
        if (side == kLeft || side == kRight)
            x.uv.x() = line, x.uv.y() = std::clamp(x.uv.y(), c.v0, c.v1);
        else
            x.uv.y() = line, x.uv.x() = std::clamp(x.uv.x(), c.u0, c.u1);
    }
    const double su = kCornerSnap * (c.u1 - c.u0), sv = kCornerSnap * (c.v1 - c.v0);
    for (double cu : {c.u0, c.u1})
        for (double cv : {c.v0, c.v1})
            if (std::abs(x.uv.x() - cu) <= su && std::abs(x.uv.y() - cv) <= sv) x.uv = {cu, cv};
    x.position = perimeter_position(c, side, x.uv);
    return x;
}

double signed_area(const std::vector<Eigen::Vector2d>& p) {
    double area = 0.0;
    for (size_t i = 0, n = p.size(); i < n; ++i) {
        const Eigen::Vector2d& a = p[i];
        const Eigen::Vector2d& b = p[(i + 1) % n];
        area += a.x() * b.y() - b.x() * a.y();
    }
    return 0.5 * area;
}

// Even-odd point in polygon (half-open in v, so vertices on the ray count once).
// Side midpoints of an island hole tested against the rings of its cell (majority).
constexpr size_t kHoleProbes = 5;

bool contains(const std::vector<Eigen::Vector2d>& poly, const Eigen::Vector2d& p) {
    bool in = false;
    for (size_t i = 0, n = poly.size(), j = n - 1; i < n; j = i++) {
        const Eigen::Vector2d& a = poly[i];
        const Eigen::Vector2d& b = poly[j];
        if ((a.y() > p.y()) != (b.y() > p.y())) {
            const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
            if (x > p.x()) in = !in;
        }
    }
    return in;
}

// Per-segment events in the cell being processed.
struct SegmentEvents {
    int stamp = -1;
    int entry = -1, exit = -1;  // indices into the cell's crossing list
};

}  // namespace

TrimmedCells trim_cells(const CellGrid& grid, const std::vector<TrimPolygon>& loops, mesh::Deadline* deadline) {
    // Flatten the segments: segment (loop l, index i) runs from point i to i+1 (cyclic).
    std::vector<int> offset(loops.size() + 1, 0);
    for (size_t l = 0; l < loops.size(); ++l)
        offset[l + 1] = offset[l] + static_cast<int>(loops[l].points.size());
    const int segment_count = offset.back();
    std::vector<std::array<Eigen::Vector2d, 2>> segments(segment_count);
    std::vector<int> loop_of(segment_count);
    for (size_t l = 0; l < loops.size(); ++l) {
        const auto& pts = loops[l].points;
        for (size_t i = 0; i < pts.size(); ++i) {
            segments[offset[l] + i] = {pts[i].uv, pts[(i + 1) % pts.size()].uv};
            loop_of[offset[l] + i] = static_cast<int>(l);
        }
    }
    const SegmentBuckets buckets(grid.box, segments);
    auto point = [&](int segment, int end) -> const PolylinePoint& {
        const int l = loop_of[segment];
        const int n = offset[l + 1] - offset[l];
        return loops[l].points[(segment - offset[l] + end) % n];
    };
    auto next_segment = [&](int segment) {
        const int l = loop_of[segment];
        return segment + 1 < offset[l + 1] ? segment + 1 : offset[l];
    };

    VertexTable table;
    TrimmedCells result;
    std::vector<int> seen(segment_count, -1);
    std::vector<SegmentEvents> events(segment_count);
    std::vector<int> candidates;
    std::vector<char> loop_inside(loops.size(), 0), loop_crossed(loops.size(), 0);

    for (size_t ci = 0; ci < grid.cells.size(); ++ci) {
        const Cell& cell = grid.cells[ci];
        const int stamp = static_cast<int>(ci);
        // Candidate segments: those in the buckets the cell overlaps, ascending.
        candidates.clear();
        for (int i = buckets.column(cell.u0); i <= buckets.column(cell.u1); ++i)
            for (int j = buckets.row(cell.v0); j <= buckets.row(cell.v1); ++j)
                for (int s : buckets.bucket(i, j)) {
                    mesh::check_deadline(deadline, "trimming the cells");
                    if (seen[s] != stamp) seen[s] = stamp, candidates.push_back(s);
                }
        std::sort(candidates.begin(), candidates.end());

        // Crossings with the cell's sides.
        std::vector<Crossing> crossings;
        std::vector<int> entries;  // crossing indices that enter the cell
        std::vector<int> touched_loops;
        for (int s : candidates) {
            mesh::check_deadline(deadline, "trimming the cells");
            const PolylinePoint& a = point(s, 0);
            const PolylinePoint& b = point(s, 1);
            const bool in_a = inside(cell, a.uv), in_b = inside(cell, b.uv);
            const int l = loop_of[s];
            if (in_a || in_b) {
                if (!loop_inside[l] && !loop_crossed[l]) touched_loops.push_back(l);
                loop_inside[l] = 1;
            }
            if (in_a && in_b) continue;
            const Clip r = clip(cell, a.uv, b.uv);
            const bool enters = !in_a && (in_b || r.lo < r.hi);
            const bool leaves = !in_b && (in_a || r.lo < r.hi);
            if (!enters && !leaves) continue;
            if (!loop_inside[l] && !loop_crossed[l]) touched_loops.push_back(l);
            loop_crossed[l] = 1;
            SegmentEvents& e = events[s];
            e.stamp = stamp;
            e.entry = e.exit = -1;
            if (enters) {
                const int side = r.lo_side >= 0 ? r.lo_side : kLeft;
                e.entry = static_cast<int>(crossings.size());
                crossings.push_back(crossing(cell, a, b, side));
                entries.push_back(e.entry);
            }
            if (leaves) {
                const int side = r.hi_side >= 0 ? r.hi_side : kRight;
                e.exit = static_cast<int>(crossings.size());
                crossings.push_back(crossing(cell, a, b, side));
            }
        }
        auto events_of = [&](int s) -> const SegmentEvents* {
            return events[s].stamp == stamp ? &events[s] : nullptr;
        };

        // Pieces: trim chains from an entry to the next exit.
        struct Piece {
            std::vector<int> vertices;
            int entry = -1, exit = -1;  // crossing indices
            bool used = false;
            // Trim points just before the entry and just after the exit (outside the
            // cell): they orient a piece that only touches a side at one point.
            Eigen::Vector2d before, after;
        };
        std::vector<Piece> pieces;
        std::vector<int> piece_of_entry(crossings.size(), -1);
        for (int s : candidates) {
            mesh::check_deadline(deadline, "trimming the cells");
            const SegmentEvents* e = events_of(s);
            if (!e || e->entry < 0) continue;
            Piece piece;
            piece.entry = e->entry;
            piece.before = point(s, 0).uv;
            piece.vertices.push_back(table.add(crossings[e->entry].uv, &crossings[e->entry].xyz, crossings[e->entry].removable));
            int current = s;
            const int limit = offset[loop_of[s] + 1] - offset[loop_of[s]] + 1;
            for (int step = 0; step <= limit; ++step) {
                const SegmentEvents* ce = events_of(current);
                if (ce && ce->exit >= 0) {
                    piece.exit = ce->exit;
                    piece.after = point(current, 1).uv;
                    break;
                }
                const PolylinePoint& b = point(current, 1);
                piece.vertices.push_back(table.add(b.uv, &b.xyz));
                current = next_segment(current);
            }
            if (piece.exit < 0) continue;  // inconsistent trims; dropped
            piece.vertices.push_back(table.add(crossings[piece.exit].uv, &crossings[piece.exit].xyz, crossings[piece.exit].removable));
            for (size_t k = 0; k + 1 < piece.vertices.size(); ++k)
                if (piece.vertices[k] != piece.vertices[k + 1])
                    result.trim_edges.push_back({piece.vertices[k], piece.vertices[k + 1]});
            piece_of_entry[piece.entry] = static_cast<int>(pieces.size());
            pieces.push_back(std::move(piece));
        }

        // Boundary points of the cell with their perimeter positions.
        const auto& boundary = grid.boundary[ci];
        std::vector<double> boundary_pos(boundary.size());
        for (size_t k = 0; k < boundary.size(); ++k) boundary_pos[k] = boundary_position(cell, boundary[k]);
        auto forward = [](double from, double to) {
            double d = to - from;
            return d < 0.0 ? d + 4.0 : d;
        };
        auto add_boundary = [&](std::vector<int>& ring, double from, double span) {
            std::vector<std::pair<double, int>> between;
            for (size_t k = 0; k < boundary.size(); ++k) {
                const double d = forward(from, boundary_pos[k]);
                if (d > 0.0 && d < span) between.emplace_back(d, static_cast<int>(k));
            }
            std::sort(between.begin(), between.end());
            for (const auto& [d, k] : between) ring.push_back(table.add(boundary[k], nullptr));
        };

        std::vector<std::vector<int>> rings;
        for (size_t start = 0; start < pieces.size(); ++start) {
            if (pieces[start].used) continue;
            std::vector<int> ring;
            size_t current = start;
            bool closed = false;
            for (size_t guard = 0; guard <= pieces.size(); ++guard) {
                Piece& piece = pieces[current];
                piece.used = true;
                ring.insert(ring.end(), piece.vertices.begin(), piece.vertices.end());
                // Next entry counter-clockwise from this exit.
                const double from = crossings[piece.exit].position;
                int best = -1;
                double best_d = 5.0;
                for (int x : entries) {
                    mesh::check_deadline(deadline, "trimming the cells");
                    const int pi = piece_of_entry[x];
                    if (pi < 0) continue;
                    double d = forward(from, crossings[x].position);
                    if (d == 0.0 && static_cast<size_t>(pi) == current) {
                        // A chain leaving where it entered: a clockwise one (a hole touching
                        // the side) keeps the whole perimeter, a counter-clockwise one none.
                        // A chain that only touches the side (a trim vertex on it, zero
                        // area) turns by the trim points around it: turning clockwise, the
                        // kept region (on the left) is the cell's side.
                        std::vector<Eigen::Vector2d> uv;
                        for (int v : piece.vertices) uv.push_back(table.uv(v));
                        double area = signed_area(uv);
                        if (area == 0.0)
                            area = signed_area({piece.before, table.uv(piece.vertices.front()), piece.after});
                        if (area < 0.0) d = 4.0;
                    } else if (d == 0.0) {
                        // Another chain entering where this one leaves: the trim touches the
                        // side from inside. Turning clockwise there, the kept region reaches
                        // the side, so the ring follows the perimeter instead.
                        const Eigen::Vector2d at = crossings[piece.exit].uv;
                        Eigen::Vector2d in = piece.before, out = pieces[pi].after;
                        for (auto it = piece.vertices.rbegin(); it != piece.vertices.rend(); ++it)
                            if (table.uv(*it) != at) { in = table.uv(*it); break; }
                        for (int v : pieces[pi].vertices)
                            if (table.uv(v) != at) { out = table.uv(v); break; }
                        if (signed_area({in, at, out}) < 0.0) d = 4.0;
                    }
                    if (d < best_d) best_d = d, best = pi;
                }
                if (best < 0) break;
                add_boundary(ring, from, best_d);
                if (static_cast<size_t>(best) == start) {
                    closed = true;
                    break;
                }
                if (pieces[best].used) break;  // inconsistent trims
                current = static_cast<size_t>(best);
            }
            if (closed) rings.push_back(std::move(ring));
        }
        // Loops entirely inside the cell (islands), and the cell's status without pieces.
        std::vector<int> islands;
        for (int l : touched_loops) {
            if (loop_inside[l] && !loop_crossed[l]) islands.push_back(l);
            loop_inside[l] = loop_crossed[l] = 0;
        }
        if (pieces.empty()) {
            // Ray from the centre towards +u over the loops that are not islands here.
            const Eigen::Vector2d centre(0.5 * (cell.u0 + cell.u1), 0.5 * (cell.v0 + cell.v1));
            bool in = false;
            const int row = buckets.row(centre.y());
            const int stamp2 = -2 - static_cast<int>(ci);
            for (int i = buckets.column(centre.x()); i < buckets.count(); ++i)
                for (int s : buckets.bucket(i, row)) {
                    if (seen[s] == stamp2) continue;
                    seen[s] = stamp2;
                    if (std::find(islands.begin(), islands.end(), loop_of[s]) != islands.end()) continue;
                    const Eigen::Vector2d& a = segments[s][0];
                    const Eigen::Vector2d& b = segments[s][1];
                    if ((a.y() > centre.y()) != (b.y() > centre.y())) {
                        const double x = a.x() + (centre.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
                        if (x > centre.x()) in = !in;
                    }
                }
            if (in) {
                std::vector<int> ring;
                for (const auto& p : boundary) ring.push_back(table.add(p, nullptr));
                rings.push_back(std::move(ring));
            }
        }
        const bool whole = pieces.empty() && !rings.empty();

        // Islands: counter-clockwise ones are polygons, clockwise ones holes.
        std::vector<std::vector<int>> holes;
        for (int l : islands) {
            std::vector<int> ring;
            std::vector<Eigen::Vector2d> uv;
            for (const PolylinePoint& p : loops[l].points) {
                ring.push_back(table.add(p.uv, &p.xyz));
                uv.push_back(p.uv);
            }
            for (size_t k = 0; k < ring.size(); ++k)
                if (ring[k] != ring[(k + 1) % ring.size()])
                    result.trim_edges.push_back({ring[k], ring[(k + 1) % ring.size()]});
            if (signed_area(uv) >= 0.0)
                rings.push_back(std::move(ring));
            else
                holes.push_back(std::move(ring));
        }

        // Emit polygons: consecutive duplicates removed, holes assigned to containing rings.
        const size_t first_polygon = result.polygons.size();
        for (auto& ring : rings) {
            std::vector<int> clean;
            for (int v : ring)
                if (clean.empty() || clean.back() != v) clean.push_back(v);
            while (clean.size() > 1 && clean.front() == clean.back()) clean.pop_back();
            if (clean.size() < 3) continue;
            CellPolygon polygon;
            polygon.outer = std::move(clean);
            polygon.cell = static_cast<int>(ci);
            polygon.whole_cell = whole;
            result.polygons.push_back(std::move(polygon));
        }
        for (auto& hole : holes) {
            // Probes at midpoints of the hole's sides, not at its vertices: a hole may
            // touch its ring at a vertex (a circle tangent inside another, both loops
            // starting at the touching point), where containment is undecided.
            std::vector<Eigen::Vector2d> probes;
            const size_t step = std::max<size_t>(1, hole.size() / kHoleProbes);
            for (size_t k = 0; k < hole.size() && probes.size() < kHoleProbes; k += step)
                probes.push_back(0.5 * (table.uv(hole[k]) + table.uv(hole[(k + 1) % hole.size()])));
            for (size_t k = first_polygon; k < result.polygons.size(); ++k) {
                std::vector<Eigen::Vector2d> uv;
                for (int v : result.polygons[k].outer) uv.push_back(table.uv(v));
                size_t in = 0;
                for (const Eigen::Vector2d& probe : probes) in += contains(uv, probe) ? 1 : 0;
                if (2 * in > probes.size()) {
                    result.polygons[k].holes.push_back(std::move(hole));
                    result.polygons[k].whole_cell = false;
                    break;
                }
            }
        }
    }
    result.vertices = table.take();
    return result;
}

}  // namespace trimkit::tess
