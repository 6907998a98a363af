// Validation and queries on knot vectors U = {u_0 .. u_m}, stored as plain
// std::vector<double>. A valid vector is finite, non-decreasing, has
// m + 1 = #points + p + 1 entries, no knot of multiplicity above p + 1,
// and a non-empty domain U[p] < U[n+1]. Unclamped ends are allowed.
#pragma once

#include <string>
#include <vector>

namespace trimkit::geom {

// Relative tolerance for comparing knots: two knots closer than
// kKnotTolerance * (domain length) are the same knot. Chosen far above double
// rounding (1e-16) and far below any real CAD knot spacing (>= 1e-6 relative).
constexpr double kKnotTolerance = 1e-10;

// Throws InvalidInput naming `owner` when U is not a valid knot vector for
// degree p and `point_count` control points.
void validate_knot_vector(const std::vector<double>& U, int p, int point_count,
                          const std::string& owner);

// Distinct knot values inside the domain [U[p], U[n+1]], both ends included.
std::vector<double> distinct_knots(const std::vector<double>& U, int p);

// Whether both ends of U carry p + 1 equal knots (the curve or surface passes
// through its end poles; its end spans' poles are the first and last p + 1).
bool is_clamped(const std::vector<double>& U, int p);

// Multiplicity of knot value u in U (knots within kKnotTolerance * domain length).
int knot_multiplicity(const std::vector<double>& U, double u);

// t moved onto the nearest knot of U when closer than tol (callers pass
// kKnotTolerance * domain length), so near-duplicate knots are never created.
double snap_to_knot(const std::vector<double>& U, double t, double tol);

// Clamped uniform knot vector for n+1 points of degree p on [a, b].
std::vector<double> uniform_clamped_knots(int point_count, int p, double a = 0.0,
                                          double b = 1.0);

// Knot vector of a single Bézier segment of degree p on [a, b]: p+1 a's, p+1 b's.
std::vector<double> bezier_knots(int p, double a = 0.0, double b = 1.0);

}  // namespace trimkit::geom
