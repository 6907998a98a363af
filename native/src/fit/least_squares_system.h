// LeastSquaresSystem: min Σ_r w_r² (a_r·x - b_r)² over a vector x of unknowns, some
// of which are fixed to given values and eliminated before solving. The fitters
// put a control point's three coordinates at unknowns 3k, 3k+1, 3k+2, so a row may
// couple them (a tangent-plane row n·S_u = 0). Solved through the normal equations
// with a sparse LDLT factorisation (the rows are local: p+1 basis functions each).
#pragma once

#include <utility>
#include <vector>

#include <Eigen/Core>

namespace trimkit::fit {

class LeastSquaresSystem {
public:
    explicit LeastSquaresSystem(int unknowns);

    int unknowns() const { return n_; }
    int rows() const { return static_cast<int>(b_.size()); }

    // Adds the row w (a·x - b); a lists (unknown, coefficient) pairs.
    void add_row(const std::vector<std::pair<int, double>>& a, double b, double weight);
    // Fixes unknown i to value (a later fix of the same unknown replaces it).
    void fix(int i, double value);
    bool is_fixed(int i) const { return fixed_[i]; }

    // The minimiser, fixed unknowns at their values. Throws geom::NumericalFailure
    // naming `owner` if the free unknowns are not determined by the rows.
    Eigen::VectorXd solve(const char* owner) const;

private:
    int n_;
    std::vector<std::vector<std::pair<int, double>>> a_;
    std::vector<double> b_, w_;
    std::vector<bool> fixed_;
    std::vector<double> value_;
};

}  // namespace trimkit::fit
