#include "fit/smoothing_rows.h"

#include <cmath>
#include <utility>
#include <vector>

namespace trimkit::fit {

void add_smoothing_rows(LeastSquaresSystem& system, int nu, int nv, double weight) {
    const auto index = [nv](int i, int j, int c) { return 3 * (i * nv + j) + c; };
    using Stencil = std::vector<std::pair<std::pair<int, int>, double>>;
    std::vector<std::pair<std::pair<int, int>, Stencil>> stencils;
    for (int i = 0; i < nu; ++i)
        for (int j = 0; j < nv; ++j) {
            if (i > 0 && i + 1 < nu) stencils.push_back({{i, j}, {{{-1, 0}, 1.0}, {{0, 0}, -2.0}, {{1, 0}, 1.0}}});
            if (j > 0 && j + 1 < nv) stencils.push_back({{i, j}, {{{0, -1}, 1.0}, {{0, 0}, -2.0}, {{0, 1}, 1.0}}});
            if (i + 1 < nu && j + 1 < nv) {
                const double s = std::sqrt(2.0);
                stencils.push_back({{i, j}, {{{0, 0}, s}, {{1, 0}, -s}, {{0, 1}, -s}, {{1, 1}, s}}});
            }
        }
    if (stencils.empty()) return;
    const double w = weight / std::sqrt(static_cast<double>(stencils.size()));
    for (const auto& [at, stencil] : stencils)
        for (int c = 0; c < 3; ++c) {
            std::vector<std::pair<int, double>> row;
            for (const auto& [offset, coefficient] : stencil)
                row.emplace_back(index(at.first + offset.first, at.second + offset.second, c), coefficient);
            system.add_row(row, 0.0, w);
        }
}

}  // namespace trimkit::fit
