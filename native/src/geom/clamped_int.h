// A double as an integer in [lo, hi], clamped before the conversion: converting a
// double outside the integer type's range is undefined behaviour (UBSan: a B-spline
// face's trim range 1e16 periods from its domain, fuzz_brep). NaN gives lo. x is
// expected rounded already (std::floor, std::ceil); the conversion truncates. Int is
// int or std::int64_t (lo and hi exactly representable as doubles).
#pragma once

namespace trimkit::geom {

template <class Int>
Int clamped_int(double x, Int lo, Int hi) {
    if (!(x > static_cast<double>(lo))) return lo;
    if (x >= static_cast<double>(hi)) return hi;
    return static_cast<Int>(x);
}

}  // namespace trimkit::geom
