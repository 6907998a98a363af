#include "fit/least_squares_system.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cmath>
#include <string>

#include "geom/error.h"

namespace trimkit::fit {
namespace {

// Relative size below which a pivot of the normal equations counts as zero: the
// free unknowns are then not determined (the paper's Fig. 17 failure, when
// samples are fewer than control points and no smoothing term is given).
constexpr double kSingularPivot = 1e-13;

}  // namespace

LeastSquaresSystem::LeastSquaresSystem(int unknowns)
    : n_(unknowns), fixed_(unknowns, false), value_(unknowns, 0.0) {}

void LeastSquaresSystem::add_row(const std::vector<std::pair<int, double>>& a, double b, double weight) {
    a_.push_back(a);
    b_.push_back(b);
    w_.push_back(weight);
}

void LeastSquaresSystem::fix(int i, double value) {
    fixed_[i] = true;
    value_[i] = value;
}

Eigen::VectorXd LeastSquaresSystem::solve(const char* owner) const {
    std::vector<int> column(n_, -1);
    int free = 0;
    for (int i = 0; i < n_; ++i)
        if (!fixed_[i]) column[i] = free++;
    Eigen::VectorXd x(n_);
    for (int i = 0; i < n_; ++i) x[i] = value_[i];
    if (free == 0) return x;
    // Rows with fixed unknowns moved to the right-hand side: w (A_free x_free) = w (b - A_fixed x_fixed).
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::VectorXd rhs(rows());
    for (int r = 0; r < rows(); ++r) {
        double b = b_[r];
        for (const auto& [i, c] : a_[r]) {
            if (fixed_[i]) b -= c * value_[i];
            else entries.emplace_back(r, column[i], w_[r] * c);
        }
        rhs[r] = w_[r] * b;
    }
    Eigen::SparseMatrix<double> A(rows(), free);
    A.setFromTriplets(entries.begin(), entries.end());
    const Eigen::SparseMatrix<double> AtA = A.transpose() * A;
    const Eigen::VectorXd Atb = A.transpose() * rhs;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(AtA);
    double largest = 0;
    for (int k = 0; k < free; ++k) largest = std::max(largest, AtA.coeff(k, k));
    const Eigen::VectorXd D = ldlt.info() == Eigen::Success ? ldlt.vectorD() : Eigen::VectorXd();
    if (ldlt.info() != Eigen::Success || D.size() != free || !(largest > 0) ||
        (D.array() <= kSingularPivot * largest).any())
        throw geom::NumericalFailure(std::string(owner) + ": " + std::to_string(free) +
                                     " free unknowns are not determined by " + std::to_string(rows()) +
                                     " rows (too few samples and no smoothing)");
    const Eigen::VectorXd y = ldlt.solve(Atb);
    if (!y.allFinite()) throw geom::NumericalFailure(std::string(owner) + ": non-finite solution");
    for (int i = 0; i < n_; ++i)
        if (!fixed_[i]) x[i] = y[column[i]];
    return x;
}

}  // namespace trimkit::fit
