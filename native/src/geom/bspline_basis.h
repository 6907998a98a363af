// B-spline basis functions over a knot vector U = {u_0 .. u_m} of degree p.
// Conventions: n = #control points - 1, m = n + p + 1; the valid domain is
// [U[p], U[n+1]]. All functions assume a validated knot vector (see KnotVector).
#pragma once

#include <vector>

namespace trimkit::geom {

// Maximum degree accepted anywhere in trimkit; readers reject larger degrees
// before allocating, so file values never drive unbounded work.
constexpr int kMaxDegree = 32;

// Knot span index i with U[i] <= u < U[i+1]. [PT] Sec. 2.5, Algorithm A2.1.
// Departure: u >= U[n+1] maps to span n and u <= U[p] to span p (clamped), so the
// closed end of the domain belongs to the last span.
int knot_span(const std::vector<double>& U, int p, double u);

// The p+1 non-vanishing basis functions N_{i-p,p}(u) .. N_{i,p}(u) at span i.
// [PT] Algorithm A2.2. N must have room for p+1 values.
void basis_functions(const std::vector<double>& U, int p, int span, double u, double* N);

// Basis functions and their derivatives up to order n (n <= p allowed larger:
// derivatives above p are zero). ders is (n+1) x (p+1), row k = k-th derivative.
// [PT] Algorithm A2.3.
std::vector<std::vector<double>> basis_function_derivatives(
    const std::vector<double>& U, int p, int span, double u, int n);

// The same without allocation, for evaluation loops: ders must have room for
// (n+1) * (p+1) values, row-major (ders[k * (p+1) + j] = k-th derivative of
// N_{span-p+j,p}).
void basis_function_derivatives(const std::vector<double>& U, int p, int span, double u,
                                int n, double* ders);

}  // namespace trimkit::geom
