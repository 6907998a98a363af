#include "geom/arc_parameter_map.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "geom/error.h"
#include "geom/clamped_int.h"

namespace trimkit::geom {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

ArcParameterMap::ArcParameterMap(double theta0, double theta1)
    : theta0_(theta0), theta1_(theta1) {
    if (!std::isfinite(theta0) || !std::isfinite(theta1)) {
        std::ostringstream msg;
        msg << "ArcParameterMap: angles (" << theta0 << ", " << theta1
            << ") must be finite";
        throw InvalidInput(msg.str());
    }
    const double sweep = theta1 - theta0;
    if (sweep == 0.0) {
        std::ostringstream msg;
        msg << "ArcParameterMap: start and end angle are both " << theta0
            << "; expected a non-empty arc";
        throw InvalidInput(msg.str());
    }
    if (std::abs(sweep) > 2 * kPi + kAngleSlack) {
        std::ostringstream msg;
        msg << "ArcParameterMap: sweep " << sweep << " rad from " << theta0 << " to "
            << theta1 << "; expected |sweep| <= 2π";
        throw InvalidInput(msg.str());
    }
    sigma_ = sweep > 0 ? 1 : -1;
    k_ = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / (kPi / 2) - kAngleSlack)));
    half_ = sweep / (2 * k_);
    tan_quarter_ = std::tan(std::abs(half_) / 2);
    a_.resize(k_ + 1);
    t_.resize(k_ + 1);
    for (int i = 0; i <= k_; ++i) a_[i] = theta0 + sweep * i / k_;
    a_[k_] = theta1;  // exact end, independent of rounding in the sum
    for (int i = 0; i <= k_; ++i) t_[i] = sigma_ * a_[i];
}

int ArcParameterMap::segment_of(double lambda) const {
    const double step = 2 * std::abs(half_);
    int i = clamped_int(std::floor((lambda - t_[0]) / step), 0, k_ - 1);
    // Rounding in the division can land one segment off near a knot.
    if (i > 0 && lambda < t_[i]) --i;
    if (i < k_ - 1 && lambda >= t_[i + 1]) ++i;
    return i;
}

double ArcParameterMap::to_nurbs(double theta) const {
    const double lambda = std::clamp(sigma_ * theta, t_.front(), t_.back());
    const int i = segment_of(lambda);
    const double alpha = std::abs(half_);
    const double psi = lambda - t_[i] - alpha;  // in [-α, α]
    const double s = 0.5 * (1.0 + std::tan(psi / 2) / tan_quarter_);
    if (s <= 0.0) return t_[i];
    if (s >= 1.0) return t_[i + 1];
    return t_[i] + 2 * alpha * s;
}

double ArcParameterMap::to_angle(double t) const {
    const double tc = std::clamp(t, t_.front(), t_.back());
    const int i = segment_of(tc);
    const double alpha = std::abs(half_);
    const double s = std::clamp((tc - t_[i]) / (2 * alpha), 0.0, 1.0);
    if (s == 0.0) return a_[i];
    if (s == 1.0) return a_[i + 1];
    const double psi = 2 * std::atan(tan_quarter_ * (2 * s - 1));
    double lambda = t_[i] + alpha + psi;
    lambda = std::clamp(lambda, t_[i], t_[i + 1]);
    return sigma_ * lambda;
}

double ArcParameterMap::nurbs_derivative(double theta) const {
    const double lambda = std::clamp(sigma_ * theta, t_.front(), t_.back());
    const int i = segment_of(lambda);
    const double alpha = std::abs(half_);
    const double psi = lambda - t_[i] - alpha;
    const double c = std::cos(psi / 2);
    // t = σ a_i + 2|α| s, s = (1 + tan(ψ/2)/τ)/2, λ = σθ
    //   =>  dt/dθ = σ |α| / (2τ cos²(ψ/2)).
    return sigma_ * alpha / (2 * tan_quarter_ * c * c);
}

std::vector<double> ArcParameterMap::knot_vector() const {
    std::vector<double> U;
    U.reserve(2 * k_ + 4);
    U.insert(U.end(), 3, t_.front());
    for (int i = 1; i < k_; ++i) U.insert(U.end(), 2, t_[i]);
    U.insert(U.end(), 3, t_.back());
    return U;
}

std::vector<Eigen::Vector2d> ArcParameterMap::unit_circle_points() const {
    std::vector<Eigen::Vector2d> P(2 * k_ + 1);
    // Middle points at the mid angle, pushed out to the tangent intersection.
    const double scale = 1.0 / std::cos(half_);
    for (int i = 0; i <= k_; ++i) P[2 * i] = Eigen::Vector2d(std::cos(a_[i]), std::sin(a_[i]));
    for (int i = 0; i < k_; ++i) {
        const double m = a_[i] + half_;
        P[2 * i + 1] = scale * Eigen::Vector2d(std::cos(m), std::sin(m));
    }
    return P;
}

std::vector<double> ArcParameterMap::weights() const {
    std::vector<double> w(2 * k_ + 1, 1.0);
    const double wm = std::cos(half_);
    for (int i = 0; i < k_; ++i) w[2 * i + 1] = wm;
    return w;
}

}  // namespace trimkit::geom
