#include "tbp/point_in_solid.h"

#include <array>
#include <cmath>

#include "geom/error.h"

namespace trimkit::tbp {
namespace {

// Generic directions (irrational-looking components, no axis or diagonal
// alignment), normalised at use.
const std::array<Eigen::Vector3d, 9> kRayDirections = {
    Eigen::Vector3d(0.5773502691896258, 0.6318599478453611, 0.5171043869742351),
    Eigen::Vector3d(-0.3090169943749474, 0.8090169943749475, 0.4993498701398471),
    Eigen::Vector3d(0.7453559924999299, -0.3651483716701107, 0.5577733510227171),
    Eigen::Vector3d(-0.6123724356957945, -0.4330127018922193, -0.6614378277661477),
    Eigen::Vector3d(0.1414213562373095, -0.8660254037844386, -0.4795831523312719),
    Eigen::Vector3d(-0.8944271909999159, 0.2672612419124244, -0.3585685828003181),
    Eigen::Vector3d(0.3826834323650898, 0.2236067977499790, -0.8964214570007952),
    Eigen::Vector3d(-0.2588190451025208, -0.9510565162951535, 0.1688444102130381),
    Eigen::Vector3d(0.9238795325112867, 0.1305261922200516, 0.3598678717208433),
};

bool ray_meets_box(const Eigen::Vector3d& o, const Eigen::Vector3d& inv_d, const Eigen::AlignedBox3d& box, double pad) {
    double t0 = 0.0, t1 = INFINITY;
    for (int a = 0; a < 3; ++a) {
        double ta = (box.min()[a] - pad - o[a]) * inv_d[a], tb = (box.max()[a] + pad - o[a]) * inv_d[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (t0 > t1) return false;
    }
    return true;
}

struct RayCast {
    Eigen::Vector3d o, d, inv_d;
    double pad, on_surface;
    PointInSolidStats& stats;
    int crossings = 0;
    bool ambiguous = false;
    bool boundary = false;

    void node(const TbpHierarchy& h, int l, int k) {
        if (ambiguous || boundary) return;
        const TbpNode& n = h.node(l, k);
        ++stats.box_tests;
        if (!ray_meets_box(o, inv_d, n.box, pad)) return;
        if (l < h.levels()) {
            for (int c = 0; c < h.children_per_node(); ++c) node(h, l + 1, h.first_child(k) + c);
            return;
        }
        ++stats.triangle_tests;
        // Moller-Trumbore ray/triangle.
        const Eigen::Vector3d e1 = n.base(1) - n.base(0), e2 = n.base(2) - n.base(0);
        const Eigen::Vector3d pv = d.cross(e2);
        const double det = e1.dot(pv);
        const double scale = e1.norm() * e2.norm();
        if (scale == 0) return;  // degenerate leaf: no area, no crossing
        const Eigen::Vector3d tv = o - n.base(0);
        if (std::abs(det) <= kGrazeTolerance * scale) {
            ambiguous = true;  // (nearly) parallel to a triangle in the ray's path: ill-conditioned
            return;
        }
        const double inv = 1.0 / det;
        const double b1 = tv.dot(pv) * inv;
        const Eigen::Vector3d qv = tv.cross(e1);
        const double b2 = d.dot(qv) * inv;
        const double t = e2.dot(qv) * inv;
        const double b0 = 1 - b1 - b2;
        if (b0 < -kGrazeTolerance || b1 < -kGrazeTolerance || b2 < -kGrazeTolerance) return;  // clear miss
        if (std::abs(t) <= on_surface) {
            boundary = true;
            return;
        }
        if (t < 0) return;
        if (b0 <= kGrazeTolerance || b1 <= kGrazeTolerance || b2 <= kGrazeTolerance) {
            ambiguous = true;  // through an edge or vertex: this ray cannot count it once
            return;
        }
        ++crossings;
    }
};

double solid_scale(const std::vector<TbpHierarchy>& solid) {
    Eigen::AlignedBox3d box;
    for (const TbpHierarchy& h : solid) box.extend(h.node(0, 0).box);
    return box.diagonal().norm();
}

}  // namespace

Containment point_in_solid(const std::vector<TbpHierarchy>& solid, const Eigen::Vector3d& point,
                           PointInSolidStats* stats) {
    PointInSolidStats local;
    PointInSolidStats& s = stats ? *stats : local;
    const double scale = solid_scale(solid);
    int votes_in = 0, votes_out = 0;
    for (const Eigen::Vector3d& dir : kRayDirections) {
        // boxes padded by the on-surface tolerance so rounding cannot hide a touching leaf
        RayCast ray{point, dir.normalized(), Eigen::Vector3d::Zero(), kOnSurfaceRelativeTolerance * scale,
                    kOnSurfaceRelativeTolerance * scale, s};
        ray.inv_d = ray.d.cwiseInverse();
        for (const TbpHierarchy& h : solid) ray.node(h, 0, 0);
        if (ray.boundary) return Containment::kBoundary;
        if (ray.ambiguous) {
            ++s.rejected_rays;
            continue;
        }
        (ray.crossings % 2 ? votes_in : votes_out)++;
        if (votes_in + votes_out == 3) return votes_in >= 2 ? Containment::kInside : Containment::kOutside;
    }
    if (votes_in + votes_out > 0 && votes_in != votes_out)
        return votes_in > votes_out ? Containment::kInside : Containment::kOutside;
    throw geom::NumericalFailure("point_in_solid: every ray from (" + geom::format_value(point.x()) + ", " +
                                 geom::format_value(point.y()) + ", " + geom::format_value(point.z()) +
                                 ") grazes an edge of the solid");
}

namespace {

bool any_leaf_meets(const TbpHierarchy& h, int l, int k, const Eigen::AlignedBox3d& box, PointInSolidStats& s) {
    ++s.box_tests;
    if (!h.node(l, k).box.intersects(box)) return false;
    if (l == h.levels()) return true;
    for (int c = 0; c < h.children_per_node(); ++c)
        if (any_leaf_meets(h, l + 1, h.first_child(k) + c, box, s)) return true;
    return false;
}

}  // namespace

Containment box_in_solid(const std::vector<TbpHierarchy>& solid, const Eigen::AlignedBox3d& box,
                         PointInSolidStats* stats) {
    PointInSolidStats local;
    PointInSolidStats& s = stats ? *stats : local;
    for (const TbpHierarchy& h : solid)
        if (any_leaf_meets(h, 0, 0, box, s)) return Containment::kBoundary;
    return point_in_solid(solid, box.center(), stats);
}

}  // namespace trimkit::tbp
