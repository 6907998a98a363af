#include "fit/fit_surface.h"

#include <cmath>
#include <string>
#include <tuple>
#include <utility>

#include "fit/fit_curve.h"
#include "fit/least_squares_system.h"
#include "fit/smoothing_rows.h"
#include "geom/bspline_basis.h"
#include "geom/error.h"
#include "geom/knot_vector.h"

namespace trimkit::fit {
namespace {

void validate_counts(const SurfaceFitProblem& f) {
    for (const auto& [p, n, name] : {std::tuple{f.degree_u, f.count_u, "u"}, std::tuple{f.degree_v, f.count_v, "v"}}) {
        if (p < 1 || p > geom::kMaxDegree)
            throw geom::InvalidInput(std::string("fit_surface: degree in ") + name + " " + std::to_string(p) +
                                     "; expected 1 .. " + std::to_string(geom::kMaxDegree));
        if (n < p + 1 || n > kMaxFitControlPoints)
            throw geom::InvalidInput(std::string("fit_surface: ") + std::to_string(n) + " control points in " +
                                     name + "; expected " + std::to_string(p + 1) + " .. " +
                                     std::to_string(kMaxFitControlPoints));
    }
    if (!f.fixed.empty() && f.fixed.size() != static_cast<std::size_t>(f.count_u * f.count_v))
        throw geom::InvalidInput("fit_surface: " + std::to_string(f.fixed.size()) + " fixed entries; expected " +
                                 std::to_string(f.count_u * f.count_v));
    if (!(f.smoothing >= 0) || !std::isfinite(f.smoothing) || !(f.tangent_weight >= 0) ||
        !std::isfinite(f.tangent_weight))
        throw geom::InvalidInput("fit_surface: smoothing and tangent weight must be finite and >= 0");
}

void validate_uv(const Eigen::Vector2d& uv, double weight, std::size_t k, const char* what) {
    if (!(uv.x() >= 0 && uv.x() <= 1 && uv.y() >= 0 && uv.y() <= 1) || !(weight >= 0) || !std::isfinite(weight))
        throw geom::InvalidInput(std::string("fit_surface: ") + what + " " + std::to_string(k) + " at (" +
                                 geom::format_value(uv.x()) + ", " + geom::format_value(uv.y()) +
                                 "); expected (u, v) in [0, 1]² and a finite weight >= 0");
}

// Basis values (order 0) or first derivatives (order 1) at t: p+1 values from span - p.
struct Basis {
    int span;
    std::vector<double> value, derivative;
};

Basis basis(const std::vector<double>& U, int p, double t) {
    Basis b{geom::knot_span(U, p, t), std::vector<double>(p + 1), std::vector<double>(p + 1)};
    std::vector<double> d(2 * (p + 1));
    geom::basis_function_derivatives(U, p, b.span, t, 1, d.data());
    for (int j = 0; j <= p; ++j) {
        b.value[j] = d[j];
        b.derivative[j] = d[p + 1 + j];
    }
    return b;
}

double total_weight(double sum) { return sum > 0 ? sum : 1.0; }

// Validates the samples; returns their total weights (points, tangent planes).
std::pair<double, double> validate_samples(const SurfaceFitProblem& f) {
    double point_sum = 0, tangent_sum = 0;
    for (std::size_t k = 0; k < f.points.size(); ++k) {
        validate_uv(f.points[k].uv, f.points[k].weight, k, "point");
        if (!f.points[k].x.allFinite()) throw geom::InvalidInput("fit_surface: point " + std::to_string(k) + " is not finite");
        point_sum += f.points[k].weight;
    }
    for (std::size_t k = 0; k < f.tangent_planes.size(); ++k) {
        validate_uv(f.tangent_planes[k].uv, f.tangent_planes[k].weight, k, "tangent plane");
        if (!f.tangent_planes[k].normal.allFinite())
            throw geom::InvalidInput("fit_surface: tangent plane " + std::to_string(k) + " normal is not finite");
        tangent_sum += f.tangent_planes[k].weight;
    }
    return {total_weight(point_sum), total_weight(tangent_sum)};
}

struct Net {
    int pu, pv, nu, nv;
    std::vector<double> U, V;
    int index(int i, int j, int c) const { return 3 * (i * nv + j) + c; }
};

// Point rows: S(u_k, v_k) = x_k, one row per coordinate.
void add_point_rows(LeastSquaresSystem& system, const Net& net, const std::vector<SurfaceSample>& points, double total) {
    for (const SurfaceSample& s : points) {
        const Basis bu = basis(net.U, net.pu, s.uv.x()), bv = basis(net.V, net.pv, s.uv.y());
        const double w = std::sqrt(s.weight / total);
        for (int c = 0; c < 3; ++c) {
            std::vector<std::pair<int, double>> row;
            for (int a = 0; a <= net.pu; ++a)
                for (int b = 0; b <= net.pv; ++b)
                    row.emplace_back(net.index(bu.span - net.pu + a, bv.span - net.pv + b, c), bu.value[a] * bv.value[b]);
            system.add_row(row, s.x[c], w);
        }
    }
}

// G1 rows: n·S_u = Σ N'_a(u) N_b(v) n·P_ab = 0 and the same with S_v.
void add_tangent_rows(LeastSquaresSystem& system, const Net& net, const std::vector<TangentPlaneSample>& planes,
                      double weight, double total) {
    for (const TangentPlaneSample& t : planes) {
        const Basis bu = basis(net.U, net.pu, t.uv.x()), bv = basis(net.V, net.pv, t.uv.y());
        const double w = std::sqrt(weight * t.weight / total);
        for (int direction = 0; direction < 2; ++direction) {
            std::vector<std::pair<int, double>> row;
            for (int a = 0; a <= net.pu; ++a)
                for (int b = 0; b <= net.pv; ++b) {
                    const double N = direction == 0 ? bu.derivative[a] * bv.value[b] : bu.value[a] * bv.derivative[b];
                    for (int c = 0; c < 3; ++c)
                        row.emplace_back(net.index(bu.span - net.pu + a, bv.span - net.pv + b, c), N * t.normal[c]);
                }
            system.add_row(row, 0.0, w);
        }
    }
}

}  // namespace

geom::NurbsSurface fit_surface(const SurfaceFitProblem& f) {
    validate_counts(f);
    const auto [point_total, tangent_total] = validate_samples(f);
    const Net net{f.degree_u, f.degree_v, f.count_u, f.count_v, geom::uniform_clamped_knots(f.count_u, f.degree_u),
                  geom::uniform_clamped_knots(f.count_v, f.degree_v)};
    LeastSquaresSystem system(3 * net.nu * net.nv);
    add_point_rows(system, net, f.points, point_total);
    add_tangent_rows(system, net, f.tangent_planes, f.tangent_weight, tangent_total);
    add_smoothing_rows(system, net.nu, net.nv, std::sqrt(f.smoothing));
    for (std::size_t k = 0; k < f.fixed.size(); ++k)
        if (f.fixed[k]) {
            if (!f.fixed[k]->allFinite()) throw geom::InvalidInput("fit_surface: fixed point " + std::to_string(k) + " is not finite");
            for (int c = 0; c < 3; ++c) system.fix(3 * static_cast<int>(k) + c, (*f.fixed[k])[c]);
        }
    const Eigen::VectorXd x = system.solve("fit_surface");
    std::vector<Eigen::Vector3d> P(net.nu * net.nv);
    for (int k = 0; k < net.nu * net.nv; ++k) P[k] = x.segment<3>(3 * k);
    return geom::NurbsSurface(net.pu, net.pv, net.U, net.V, net.nu, net.nv, std::move(P));
}

}  // namespace trimkit::fit
