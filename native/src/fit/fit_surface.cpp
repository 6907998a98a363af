#include "fit/fit_surface.h"

#include <cmath>
#include <string>

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

}  // namespace

geom::NurbsSurface fit_surface(const SurfaceFitProblem& f) {
    validate_counts(f);
    const int pu = f.degree_u, pv = f.degree_v, nu = f.count_u, nv = f.count_v;
    const std::vector<double> U = geom::uniform_clamped_knots(nu, pu), V = geom::uniform_clamped_knots(nv, pv);
    const auto index = [nv](int i, int j, int c) { return 3 * (i * nv + j) + c; };
    LeastSquaresSystem system(3 * nu * nv);

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
    for (const SurfaceSample& s : f.points) {
        const Basis bu = basis(U, pu, s.uv.x()), bv = basis(V, pv, s.uv.y());
        const double w = std::sqrt(s.weight / total_weight(point_sum));
        for (int c = 0; c < 3; ++c) {
            std::vector<std::pair<int, double>> row;
            for (int a = 0; a <= pu; ++a)
                for (int b = 0; b <= pv; ++b)
                    row.emplace_back(index(bu.span - pu + a, bv.span - pv + b, c), bu.value[a] * bv.value[b]);
            system.add_row(row, s.x[c], w);
        }
    }
    // G1 rows: n·S_u = Σ N'_a(u) N_b(v) n·P_ab = 0 and the same with S_v.
    for (const TangentPlaneSample& t : f.tangent_planes) {
        const Basis bu = basis(U, pu, t.uv.x()), bv = basis(V, pv, t.uv.y());
        const double w = std::sqrt(f.tangent_weight * t.weight / total_weight(tangent_sum));
        for (int direction = 0; direction < 2; ++direction) {
            std::vector<std::pair<int, double>> row;
            for (int a = 0; a <= pu; ++a)
                for (int b = 0; b <= pv; ++b) {
                    const double N = direction == 0 ? bu.derivative[a] * bv.value[b] : bu.value[a] * bv.derivative[b];
                    for (int c = 0; c < 3; ++c)
                        row.emplace_back(index(bu.span - pu + a, bv.span - pv + b, c), N * t.normal[c]);
                }
            system.add_row(row, 0.0, w);
        }
    }
    add_smoothing_rows(system, nu, nv, std::sqrt(f.smoothing));
    for (std::size_t k = 0; k < f.fixed.size(); ++k)
        if (f.fixed[k]) {
            if (!f.fixed[k]->allFinite()) throw geom::InvalidInput("fit_surface: fixed point " + std::to_string(k) + " is not finite");
            for (int c = 0; c < 3; ++c) system.fix(3 * static_cast<int>(k) + c, (*f.fixed[k])[c]);
        }
    const Eigen::VectorXd x = system.solve("fit_surface");
    std::vector<Eigen::Vector3d> P(nu * nv);
    for (int k = 0; k < nu * nv; ++k) P[k] = x.segment<3>(3 * k);
    return geom::NurbsSurface(pu, pv, U, V, nu, nv, std::move(P));
}

}  // namespace trimkit::fit
