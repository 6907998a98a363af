// The only place where numpy arrays and Eigen/std containers convert
// (STYLE.md Sec. 7). Bulk data leaves as (n, k) float64 / int32 arrays.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include <Eigen/Core>

namespace trimkit::bindings {

namespace py = pybind11;
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// (n, Dim) float64 array from n fixed-size Eigen vectors.
template <int Dim>
py::array_t<double> to_numpy(const std::vector<Eigen::Matrix<double, Dim, 1>>& points) {
    py::array_t<double> out({static_cast<py::ssize_t>(points.size()), static_cast<py::ssize_t>(Dim)});
    auto view = out.template mutable_unchecked<2>();
    for (size_t i = 0; i < points.size(); ++i)
        for (int k = 0; k < Dim; ++k) view(i, k) = points[i][k];
    return out;
}

// Checks that `a` has shape (n, columns) and returns n; throws ValueError
// naming `what` and the expected shape otherwise.
inline py::ssize_t expect_columns(const DoubleArray& a, py::ssize_t columns, const std::string& what) {
    if (a.ndim() != 2 || a.shape(1) != columns)
        throw py::value_error(what + ": expected an array of shape (n, " + std::to_string(columns) +
                              "), got " + std::to_string(a.ndim()) + " dimensions");
    return a.shape(0);
}

}  // namespace trimkit::bindings
