// A double as an int in [lo, hi], clamped before the conversion: converting a double
// outside int's range is undefined behaviour (UBSan: a B-spline face's trim range 1e16
// periods from its domain, fuzz_brep). NaN gives lo. x is expected rounded already
// (std::floor, std::ceil); the conversion truncates.
#pragma once

namespace trimkit::geom {

inline int clamped_int(double x, int lo, int hi) {
    if (!(x > lo)) return lo;
    if (x >= hi) return hi;
    return static_cast<int>(x);
}

}  // namespace trimkit::geom
