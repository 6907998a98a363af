// The smoothing term of the fitters: a discrete thin-plate energy of the control
// net, Σ |P_{i-1,j} - 2P_{ij} + P_{i+1,j}|² + 2 |ΔuΔv P_ij|² + |P_{i,j-1} - 2P_{ij} +
// P_{i,j+1}|², whose minimum among nets is any affine (planar, evenly spaced) net. It
// keeps the least-squares system well posed where samples are few, the failure the
// paper reports (Fig. 17, Sec. 6); a curve is a net with count_v = 1.
#pragma once

#include "fit/least_squares_system.h"

namespace trimkit::fit {

// Adds the energy's rows (three per coordinate, unknowns 3 (i nv + j) + c), each
// with `weight`; total weight is normalised by the number of rows, so `weight²`
// times the row count is comparable to the sample rows' total.
void add_smoothing_rows(LeastSquaresSystem& system, int count_u, int count_v, double weight);

}  // namespace trimkit::fit
