// parallel_sort: a sort of 10^5-10^6 items (the joining stages of tess group every
// vertex by position, and every triangle side by edge, several times) as two halves on
// up to two threads, then one merge. The halves are fixed by the count alone, so the
// result is the same on any number of threads; with stable sorts of the halves (and
// std::inplace_merge, which is stable) it equals std::stable_sort's.
#pragma once

#include <algorithm>
#include <functional>
#include <iterator>

#include "mesh/parallel_for.h"

namespace trimkit::mesh {

// Below this many items one plain sort is faster than two threads.
constexpr std::ptrdiff_t kParallelSortMin = 1 << 14;

template <class It, class Less>
void parallel_sort(It first, It last, int threads, Less less, bool stable = false) {
    const std::ptrdiff_t n = std::distance(first, last);
    const auto sort = [&](It a, It b) { stable ? std::stable_sort(a, b, less) : std::sort(a, b, less); };
    if (n < kParallelSortMin) {
        sort(first, last);
        return;
    }
    const It middle = first + n / 2;
    parallel_for(2, threads, [&](int half) { half == 0 ? sort(first, middle) : sort(middle, last); });
    std::inplace_merge(first, middle, last, less);
}

template <class It>
void parallel_sort(It first, It last, int threads) {
    parallel_sort(first, last, threads, std::less<>());
}

}  // namespace trimkit::mesh
