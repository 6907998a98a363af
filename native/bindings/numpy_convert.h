// The only place where numpy arrays and Eigen/std containers convert
// (STYLE.md Sec. 7). Bulk data leaves as (n, k) float64 / int32 arrays.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
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

using IntArray = py::array_t<std::int32_t, py::array::c_style | py::array::forcecast>;

// (n, Dim) array of Scalar from n fixed-size rows (std::array or Eigen vectors).
template <typename Scalar, int Dim, typename Rows>
py::array_t<Scalar> rows_to_numpy(const Rows& rows) {
    py::array_t<Scalar> out({static_cast<py::ssize_t>(rows.size()), static_cast<py::ssize_t>(Dim)});
    auto view = out.template mutable_unchecked<2>();
    for (size_t i = 0; i < rows.size(); ++i)
        for (int k = 0; k < Dim; ++k) view(i, k) = static_cast<Scalar>(rows[i][k]);
    return out;
}

// (n,) array from a vector.
template <typename Scalar, typename T>
py::array_t<Scalar> to_numpy_1d(const std::vector<T>& values) {
    py::array_t<Scalar> out(static_cast<py::ssize_t>(values.size()));
    auto view = out.template mutable_unchecked<1>();
    for (size_t i = 0; i < values.size(); ++i) view(i) = static_cast<Scalar>(values[i]);
    return out;
}

// Checks an (n, columns) array (any n when `rows` < 0, else exactly `rows`) and
// copies it into `out` as n fixed-size rows; throws ValueError naming `what`.
template <typename Array, typename Row>
void rows_from_numpy(const Array& a, py::ssize_t columns, py::ssize_t rows, const std::string& what,
                     std::vector<Row>& out) {
    if (a.ndim() != 2 || a.shape(1) != columns || (rows >= 0 && a.shape(0) != rows))
        throw py::value_error(what + ": expected an array of shape (" +
                              (rows >= 0 ? std::to_string(rows) : std::string("n")) + ", " +
                              std::to_string(columns) + ")");
    auto view = a.template unchecked<2>();
    out.resize(static_cast<size_t>(a.shape(0)));
    for (py::ssize_t i = 0; i < a.shape(0); ++i)
        for (py::ssize_t k = 0; k < columns; ++k) out[i][k] = view(i, k);
}

// Checks a (rows,) array and copies it into `out`; throws ValueError naming `what`.
template <typename Array, typename T>
void values_from_numpy(const Array& a, py::ssize_t rows, const std::string& what, std::vector<T>& out) {
    if (a.ndim() != 1 || a.shape(0) != rows)
        throw py::value_error(what + ": expected an array of shape (" + std::to_string(rows) + ",)");
    auto view = a.template unchecked<1>();
    out.resize(static_cast<size_t>(rows));
    for (py::ssize_t i = 0; i < rows; ++i) out[i] = static_cast<T>(view(i));
}

// (p, k, 3) float64 array from p groups of k points each (all groups of size k).
inline py::array_t<double> groups_to_numpy(const std::vector<std::vector<Eigen::Vector3d>>& groups, py::ssize_t k) {
    py::array_t<double> out({static_cast<py::ssize_t>(groups.size()), k, py::ssize_t{3}});
    auto view = out.mutable_unchecked<3>();
    for (size_t g = 0; g < groups.size(); ++g)
        for (py::ssize_t i = 0; i < k; ++i)
            for (int c = 0; c < 3; ++c) view(g, i, c) = groups[g][i][c];
    return out;
}

// Checks a (p, k, 3) array (k = `k`) and returns its p groups of k points;
// throws ValueError naming `what` and the expected shape.
inline std::vector<std::vector<Eigen::Vector3d>> groups_from_numpy(const DoubleArray& a, py::ssize_t k,
                                                                   const std::string& what) {
    if (a.ndim() != 3 || a.shape(1) != k || a.shape(2) != 3)
        throw py::value_error(what + ": expected an array of shape (p, " + std::to_string(k) + ", 3)");
    auto view = a.unchecked<3>();
    std::vector<std::vector<Eigen::Vector3d>> out(static_cast<size_t>(a.shape(0)));
    for (py::ssize_t g = 0; g < a.shape(0); ++g) {
        out[g].resize(static_cast<size_t>(k));
        for (py::ssize_t i = 0; i < k; ++i) out[g][i] = Eigen::Vector3d(view(g, i, 0), view(g, i, 1), view(g, i, 2));
    }
    return out;
}

}  // namespace trimkit::bindings
