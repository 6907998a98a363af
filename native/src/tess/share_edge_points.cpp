#include "tess/share_edge_points.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "geom/error.h"

namespace trimkit::tess {

namespace {

// Coarse samples per point of the edge, and bounds on their number: enough that
// the nearest sample lies in the basin of the true foot point for curves whose
// lifted image does not fold back within 1/kMinSamples of its domain.
constexpr int kSamplesPerPoint = 8;
constexpr int kMinSamples = 64;
constexpr int kMaxSamples = 8192;
constexpr int kNewtonIterations = 30;
// Newton stops when the step is below this fraction of the domain (t resolution).
constexpr double kNewtonStepRelative = 1e-15;

struct CurveOnSurface {
    const geom::NurbsSurface& S;
    const geom::NurbsCurve2d& c;

    Eigen::Vector3d point(double t) const {
        const Eigen::Vector2d uv = c.evaluate(t);
        return S.evaluate(uv.x(), uv.y());
    }
    // Γ, Γ', Γ'' at t (chain rule).
    void derivatives(double t, Eigen::Vector3d* G, Eigen::Vector3d* G1, Eigen::Vector3d* G2) const {
        const auto cd = c.derivatives(t, 2);
        const geom::SurfaceDerivatives sd = S.derivatives(cd[0].x(), cd[0].y());
        const double u1 = cd[1].x(), v1 = cd[1].y();
        *G = sd.S;
        *G1 = sd.Su * u1 + sd.Sv * v1;
        *G2 = sd.Suu * u1 * u1 + 2.0 * sd.Suv * u1 * v1 + sd.Svv * v1 * v1 + sd.Su * cd[2].x() +
              sd.Sv * cd[2].y();
    }
};

}  // namespace

std::vector<Eigen::Vector3d> edge_points_from(const TrimPolyline& polyline, bool edge_reversed) {
    std::vector<Eigen::Vector3d> X;
    X.reserve(polyline.points.size());
    for (const PolylinePoint& p : polyline.points) X.push_back(p.xyz);
    if (edge_reversed) std::reverse(X.begin(), X.end());
    return X;
}

SharedEdgePolyline share_edge_points(const geom::NurbsSurface& S, const geom::Coedge& coedge,
                                     const std::vector<Eigen::Vector3d>& edge_points) {
    const int n = static_cast<int>(edge_points.size());
    if (n < 2)
        throw geom::InvalidInput("share_edge_points: edge " + std::to_string(coedge.edge) + " has " +
                                 std::to_string(n) + " points; expected at least 2");
    std::vector<Eigen::Vector3d> X = edge_points;
    bool reversed = coedge.edge_reversed;  // X runs against edge_points
    if (reversed) std::reverse(X.begin(), X.end());

    const CurveOnSurface G{S, coedge.curve};
    const auto [ta, tb] = coedge.curve.domain();
    const int m = std::clamp(kSamplesPerPoint * n, kMinSamples, kMaxSamples);
    std::vector<double> ts(m + 1);
    std::vector<Eigen::Vector3d> gs(m + 1);
    for (int k = 0; k <= m; ++k) {
        ts[k] = k == m ? tb : ta + (tb - ta) * k / m;
        gs[k] = G.point(ts[k]);
    }

    // The edge's points must run along the coedge's curve from ta to tb. A file may
    // give a coedge whose curve runs against its edge-reversal flag: the points then
    // run from tb to ta, and mapping them monotonically from ta would pile them at
    // one end (one uv at two positions far apart). The orientation is read from the
    // ends, or (a closed edge, whose ends coincide) from interior points' nearest
    // samples.
    {
        const double fwd = (X.front() - gs[0]).norm() + (X.back() - gs[m]).norm();
        const double rev = (X.front() - gs[m]).norm() + (X.back() - gs[0]).norm();
        bool flip = rev < 0.5 * fwd;
        if (!flip && !(fwd < 0.5 * rev) && n >= 5) {
            const auto nearest = [&](const Eigen::Vector3d& x) {
                int best = 0;
                double best_d = INFINITY;
                for (int k = 0; k <= m; ++k) {
                    const double d = (gs[k] - x).squaredNorm();
                    if (d < best_d) best_d = d, best = k;
                }
                return best;
            };
            const int k1 = nearest(X[n / 3]), k2 = nearest(X[(2 * n) / 3]);
            flip = k1 > k2;
        }
        if (flip) std::reverse(X.begin(), X.end());
        reversed = reversed != flip;
    }

    SharedEdgePolyline result;
    result.polyline.edge = coedge.edge;
    result.feet.resize(n);
    double t_prev = ta;
    int k_prev = 0;
    for (int i = 0; i < n; ++i) {
        double t;
        if (i == 0) {
            t = ta;
        } else if (i == n - 1) {
            t = tb;
        } else {
            // Nearest sample at or after the previous parameter.
            int best = k_prev;
            double best_d = INFINITY;
            for (int k = k_prev; k <= m; ++k) {
                const double d = (gs[k] - X[i]).squaredNorm();
                if (d < best_d) {
                    best_d = d;
                    best = k;
                }
            }
            // Newton on f(t) = (Γ - X)·Γ' within the samples around `best`.
            const double lo = std::max(t_prev, ts[std::max(best - 1, 0)]);
            const double hi = ts[std::min(best + 1, m)];
            t = std::clamp(ts[best], lo, hi);
            double last_step = INFINITY;
            for (int it = 0; it < kNewtonIterations; ++it) {
                Eigen::Vector3d g, g1, g2;
                G.derivatives(t, &g, &g1, &g2);
                const double f = (g - X[i]).dot(g1);
                const double df = g1.squaredNorm() + (g - X[i]).dot(g2);
                if (!(df > 0.0)) break;
                const double t_new = std::clamp(t - f / df, lo, hi);
                const double step = std::abs(t_new - t);
                t = t_new;
                // Converged, or at the rounding floor of f: a step no shorter than the
                // last one (14 % of hammer.iges's points ran all 30 iterations there).
                if (step <= kNewtonStepRelative * (tb - ta) || step >= last_step) break;
                last_step = step;
            }
            k_prev = std::max(k_prev, best - 1);
        }
        t = std::max(t, t_prev);
        t_prev = t;
        PolylinePoint p;
        p.t = t;
        p.uv = coedge.curve.evaluate(t);
        p.xyz = X[i];
        const Eigen::Vector3d foot = G.point(t);
        result.max_gap = std::max(result.max_gap, (foot - X[i]).norm());
        result.feet[reversed ? n - 1 - i : i] = foot;
        result.polyline.points.push_back(p);
    }
    return result;
}

void move_edge_points_midway(std::vector<Eigen::Vector3d>& edge_points, const std::vector<Eigen::Vector3d>& feet) {
    if (feet.size() != edge_points.size())
        throw geom::InvalidInput("move_edge_points_midway: " + std::to_string(feet.size()) + " feet for " +
                                 std::to_string(edge_points.size()) + " edge points");
    for (size_t i = 1; i + 1 < edge_points.size(); ++i) edge_points[i] = 0.5 * (edge_points[i] + feet[i]);
}

}  // namespace trimkit::tess
