#include "mesh/parallel_sort.h"

#include <gtest/gtest.h>

#include <random>
#include <utility>
#include <vector>

namespace trimkit::mesh {
namespace {

// Many equal keys, so that a sort that is not stable would show it.
std::vector<std::pair<int, int>> keyed(std::size_t n) {
    std::mt19937 rng(3);
    std::uniform_int_distribution<int> key(0, 999);
    std::vector<std::pair<int, int>> items(n);
    for (std::size_t i = 0; i < n; ++i) items[i] = {key(rng), static_cast<int>(i)};
    return items;
}

TEST(ParallelSort, StableSortEqualsStdStableSortOnAnyThreads) {
    const auto by_key = [](const std::pair<int, int>& a, const std::pair<int, int>& b) { return a.first < b.first; };
    for (std::size_t n : {std::size_t{10}, std::size_t{kParallelSortMin + 1}, std::size_t{100003}}) {
        auto expected = keyed(n);
        std::stable_sort(expected.begin(), expected.end(), by_key);
        for (int threads : {1, 2, 3}) {
            auto items = keyed(n);
            parallel_sort(items.begin(), items.end(), threads, by_key, true);
            EXPECT_EQ(items, expected) << n << " items, " << threads << " threads";
        }
    }
}

TEST(ParallelSort, SortOrdersAndKeepsEveryItem) {
    auto expected = keyed(70001);
    std::sort(expected.begin(), expected.end());
    for (int threads : {1, 2}) {
        auto items = keyed(70001);
        parallel_sort(items.begin(), items.end(), threads);
        EXPECT_EQ(items, expected);  // distinct items: one order only
    }
}

}  // namespace
}  // namespace trimkit::mesh
