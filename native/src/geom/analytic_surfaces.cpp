#include "geom/analytic_surfaces.h"

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "geom/analytic_curves.h"
#include "geom/arc_parameter_map.h"
#include "geom/compatible_curves.h"
#include "geom/error.h"

namespace trimkit::geom {

namespace {

constexpr double kPi = 3.14159265358979323846;

std::string str(const Eigen::Vector3d& v) {
    std::ostringstream s;
    s << "(" << v.transpose() << ")";
    return s.str();
}

void require(bool ok, const std::string& owner, const std::string& what) {
    if (!ok) throw InvalidInput(owner + ": " + what);
}

void require_range(double a, double b, const std::string& owner, const char* name) {
    std::ostringstream s;
    s << name << " range [" << a << ", " << b << "]; expected finite values with "
      << name << "0 < " << name << "1";
    require(std::isfinite(a) && std::isfinite(b) && a < b, owner, s.str());
}

// Orthonormal frame (X, Y, A) from an axis and a reference direction.
struct Frame {
    Eigen::Vector3d X, Y, A;
};

Frame make_frame(const Eigen::Vector3d& axis, const Eigen::Vector3d& ref_dir,
                 const std::string& owner) {
    require(axis.allFinite() && ref_dir.allFinite(), owner, "axis and ref_dir must be finite");
    require(axis.norm() > 0, owner, "axis " + str(axis) + " has zero length");
    require(ref_dir.norm() > 0, owner, "ref_dir " + str(ref_dir) + " has zero length");
    Frame f;
    f.A = axis.normalized();
    const Eigen::Vector3d r = ref_dir.normalized();
    const Eigen::Vector3d x = r - r.dot(f.A) * f.A;
    require(x.norm() > kAnalyticTolerance, owner,
            "ref_dir " + str(ref_dir) + " is parallel to the axis " + str(axis));
    f.X = x.normalized();
    f.Y = f.A.cross(f.X);
    return f;
}

ArcParameterMap increasing_arc(double theta0, double theta1, const std::string& owner,
                               const char* name) {
    require_range(theta0, theta1, owner, name);
    return ArcParameterMap(theta0, theta1);
}

// A profile (ρ_j, z_j) with weights w_j and knots V of degree q, turned about the
// frame's axis through `c` by the arc of `map` (u): P_ij = c + ρ_j (x_i X + y_i Y)
// + z_j A, weight w_i w_j, where (x_i, y_i), w_i is the unit-circle arc net.
NurbsSurface revolve_profile(const Eigen::Vector3d& c, const Frame& f, const ArcParameterMap& map,
                             int q, std::vector<double> V, const std::vector<double>& rho,
                             const std::vector<double>& z, const std::vector<double>& wv) {
    const auto Q = map.unit_circle_points();
    const auto wu = map.weights();
    const int nu = static_cast<int>(Q.size()), nv = static_cast<int>(rho.size());
    std::vector<Eigen::Vector3d> P(nu * nv);
    std::vector<double> w(nu * nv);
    for (int i = 0; i < nu; ++i) {
        const Eigen::Vector3d radial = Q[i].x() * f.X + Q[i].y() * f.Y;
        for (int j = 0; j < nv; ++j) {
            P[i * nv + j] = c + rho[j] * radial + z[j] * f.A;
            w[i * nv + j] = wu[i] * wv[j];
        }
    }
    return NurbsSurface(2, q, map.knot_vector(), std::move(V), nu, nv, std::move(P), std::move(w));
}

// Profile net of the arc (a + b cos φ, b sin φ), φ ∈ [φ0, φ1]: the sphere's and the
// torus's meridian.
void meridian(double a, double b, const ArcParameterMap& map, std::vector<double>& rho,
              std::vector<double>& z) {
    for (const Eigen::Vector2d& q : map.unit_circle_points()) {
        rho.push_back(a + b * q.x());
        z.push_back(b * q.y());
    }
}

}  // namespace

NurbsSurface plane_patch(const Eigen::Vector3d& origin, const Eigen::Vector3d& u_dir,
                         const Eigen::Vector3d& v_dir, double u0, double u1, double v0,
                         double v1) {
    const std::string owner = "plane_patch";
    require(origin.allFinite() && u_dir.allFinite() && v_dir.allFinite(), owner,
            "origin and directions must be finite");
    require(u_dir.cross(v_dir).norm() > kAnalyticTolerance * u_dir.norm() * v_dir.norm() &&
                u_dir.norm() > 0 && v_dir.norm() > 0,
            owner, "u_dir " + str(u_dir) + " and v_dir " + str(v_dir) +
                       " must be non-zero and not parallel");
    require_range(u0, u1, owner, "u");
    require_range(v0, v1, owner, "v");
    std::vector<Eigen::Vector3d> P{origin + u0 * u_dir + v0 * v_dir, origin + u0 * u_dir + v1 * v_dir,
                                   origin + u1 * u_dir + v0 * v_dir, origin + u1 * u_dir + v1 * v_dir};
    return NurbsSurface(1, 1, {u0, u0, u1, u1}, {v0, v0, v1, v1}, 2, 2, std::move(P));
}

NurbsSurface cylinder_patch(const Eigen::Vector3d& origin, const Eigen::Vector3d& axis,
                            const Eigen::Vector3d& ref_dir, double radius, double theta0,
                            double theta1, double z0, double z1) {
    const std::string owner = "cylinder_patch";
    require(origin.allFinite(), owner, "origin must be finite");
    std::ostringstream r;
    r << "radius = " << radius << "; expected a finite value > 0";
    require(std::isfinite(radius) && radius > 0, owner, r.str());
    const Frame f = make_frame(axis, ref_dir, owner);
    const ArcParameterMap map = increasing_arc(theta0, theta1, owner, "theta");
    require_range(z0, z1, owner, "z");
    return revolve_profile(origin, f, map, 1, {z0, z0, z1, z1}, {radius, radius}, {z0, z1},
                           {1, 1});
}

NurbsSurface cone_patch(const Eigen::Vector3d& origin, const Eigen::Vector3d& axis,
                        const Eigen::Vector3d& ref_dir, double radius_at_origin,
                        double semi_angle, double theta0, double theta1, double v0,
                        double v1) {
    const std::string owner = "cone_patch";
    require(origin.allFinite(), owner, "origin must be finite");
    std::ostringstream r;
    r << "radius_at_origin = " << radius_at_origin << ", semi_angle = " << semi_angle
      << "; expected radius >= 0 and |semi_angle| < π/2";
    require(std::isfinite(radius_at_origin) && radius_at_origin >= 0 &&
                std::isfinite(semi_angle) && std::abs(semi_angle) < kPi / 2,
            owner, r.str());
    const Frame f = make_frame(axis, ref_dir, owner);
    const ArcParameterMap map = increasing_arc(theta0, theta1, owner, "theta");
    require_range(v0, v1, owner, "v");
    const double slope = std::tan(semi_angle);
    return revolve_profile(origin, f, map, 1, {v0, v0, v1, v1},
                           {radius_at_origin + v0 * slope, radius_at_origin + v1 * slope},
                           {v0, v1}, {1, 1});
}

NurbsSurface sphere_patch(const Eigen::Vector3d& center, const Eigen::Vector3d& axis,
                          const Eigen::Vector3d& ref_dir, double radius, double theta0,
                          double theta1, double phi0, double phi1) {
    const std::string owner = "sphere_patch";
    require(center.allFinite(), owner, "center must be finite");
    std::ostringstream r;
    r << "radius = " << radius << "; expected a finite value > 0";
    require(std::isfinite(radius) && radius > 0, owner, r.str());
    const Frame f = make_frame(axis, ref_dir, owner);
    const ArcParameterMap mu = increasing_arc(theta0, theta1, owner, "theta");
    const ArcParameterMap mv = increasing_arc(phi0, phi1, owner, "phi");
    std::ostringstream lat;
    lat << "latitude range [" << phi0 << ", " << phi1 << "] leaves [-π/2, π/2]";
    require(phi0 >= -kPi / 2 - kAngleSlack && phi1 <= kPi / 2 + kAngleSlack, owner, lat.str());
    std::vector<double> rho, z;
    meridian(0.0, radius, mv, rho, z);
    return revolve_profile(center, f, mu, 2, mv.knot_vector(), rho, z, mv.weights());
}

NurbsSurface torus_patch(const Eigen::Vector3d& center, const Eigen::Vector3d& axis,
                         const Eigen::Vector3d& ref_dir, double major_radius,
                         double minor_radius, double theta0, double theta1, double phi0,
                         double phi1) {
    const std::string owner = "torus_patch";
    require(center.allFinite(), owner, "center must be finite");
    std::ostringstream r;
    r << "major radius = " << major_radius << ", minor radius = " << minor_radius
      << "; expected finite values > 0";
    require(std::isfinite(major_radius) && std::isfinite(minor_radius) && major_radius > 0 &&
                minor_radius > 0,
            owner, r.str());
    const Frame f = make_frame(axis, ref_dir, owner);
    const ArcParameterMap mu = increasing_arc(theta0, theta1, owner, "theta");
    const ArcParameterMap mv = increasing_arc(phi0, phi1, owner, "phi");
    std::vector<double> rho, z;
    meridian(major_radius, minor_radius, mv, rho, z);
    return revolve_profile(center, f, mu, 2, mv.knot_vector(), rho, z, mv.weights());
}

NurbsSurface surface_of_revolution(const NurbsCurve3d& generatrix,
                                   const Eigen::Vector3d& axis_point,
                                   const Eigen::Vector3d& axis_dir, double theta0,
                                   double theta1) {
    const std::string owner = "surface_of_revolution";
    require(axis_point.allFinite() && axis_dir.allFinite(), owner,
            "axis point and direction must be finite");
    require(axis_dir.norm() > 0, owner, "axis direction " + str(axis_dir) + " has zero length");
    const Eigen::Vector3d A = axis_dir.normalized();
    const ArcParameterMap map = increasing_arc(theta0, theta1, owner, "theta");
    const auto Q = map.unit_circle_points();
    const auto wv = map.weights();
    const int nu = static_cast<int>(generatrix.points().size()), nv = static_cast<int>(Q.size());
    std::vector<Eigen::Vector3d> P(nu * nv);
    std::vector<double> w(nu * nv);
    for (int i = 0; i < nu; ++i) {
        const Eigen::Vector3d& G = generatrix.points()[i];
        const Eigen::Vector3d O = axis_point + (G - axis_point).dot(A) * A;  // foot on the axis
        const Eigen::Vector3d X = G - O;  // radius and direction at angle 0
        const Eigen::Vector3d Y = A.cross(X);
        for (int j = 0; j < nv; ++j) {
            P[i * nv + j] = O + Q[j].x() * X + Q[j].y() * Y;
            w[i * nv + j] = generatrix.weights()[i] * wv[j];
        }
    }
    return NurbsSurface(generatrix.degree(), 2, generatrix.knots(), map.knot_vector(), nu, nv,
                        std::move(P), std::move(w));
}

NurbsSurface tabulated_cylinder(const NurbsCurve3d& directrix, const Eigen::Vector3d& translation,
                                double v0, double v1) {
    const std::string owner = "tabulated_cylinder";
    require(translation.allFinite() && translation.norm() > 0, owner,
            "translation " + str(translation) + "; expected a finite non-zero vector");
    require_range(v0, v1, owner, "v");
    const int nu = static_cast<int>(directrix.points().size());
    std::vector<Eigen::Vector3d> P(2 * nu);
    std::vector<double> w(2 * nu);
    for (int i = 0; i < nu; ++i) {
        P[2 * i] = directrix.points()[i] + v0 * translation;
        P[2 * i + 1] = directrix.points()[i] + v1 * translation;
        w[2 * i] = w[2 * i + 1] = directrix.weights()[i];
    }
    return NurbsSurface(directrix.degree(), 1, directrix.knots(), {v0, v0, v1, v1}, nu, 2,
                        std::move(P),
                        directrix.is_rational() ? std::move(w) : std::vector<double>{});
}

NurbsSurface ruled_surface(const NurbsCurve3d& c1, const NurbsCurve3d& c2) {
    const auto [a0, b0] = make_compatible(c1, c2);
    const auto [a, b] = make_compatible_weights(a0, b0);
    const int nu = static_cast<int>(a.points().size());
    std::vector<Eigen::Vector3d> P(2 * nu);
    std::vector<double> w(2 * nu);
    for (int i = 0; i < nu; ++i) {
        P[2 * i] = a.points()[i];
        P[2 * i + 1] = b.points()[i];
        w[2 * i] = w[2 * i + 1] = a.weights()[i];  // equal to b.weights()[i]
    }
    const bool rational = a.is_rational() || b.is_rational();
    return NurbsSurface(a.degree(), 1, a.knots(), {0.0, 0.0, 1.0, 1.0}, nu, 2, std::move(P),
                        rational ? std::move(w) : std::vector<double>{});
}

}  // namespace trimkit::geom
