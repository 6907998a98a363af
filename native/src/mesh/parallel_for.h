// parallel_for: work(i) for i in [0, n) on a few threads, items taken in turn
// (dynamic scheduling: faces differ a lot in cost). The one thread pool of the
// library's per-face and per-sample loops (tess/tessellate_model, tess/measure_deviation).
#pragma once

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace trimkit::mesh {

// `requested` threads, or (0 or less) as many as the machine has, at least 1.
inline int resolve_threads(int requested) {
    return requested > 0 ? requested : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

// Runs work(i) for i in [0, n) on min(threads, n) threads, the caller's among them; the
// first exception thrown by any item is rethrown after all threads stop (items not yet
// started are skipped).
template <class Work>
void parallel_for(int n, int threads, const Work& work) {
    std::atomic<int> next{0};
    std::exception_ptr error;
    std::mutex error_mutex;
    const auto run = [&] {
        for (int i = next++; i < n; i = next++) {
            try {
                work(i);
            } catch (...) {
                std::lock_guard<std::mutex> lock(error_mutex);
                if (!error) error = std::current_exception();
                next = n;
            }
        }
    };
    const int count = std::max(1, std::min(threads, n));
    std::vector<std::thread> pool;
    for (int t = 1; t < count; ++t) pool.emplace_back(run);
    run();
    for (auto& t : pool) t.join();
    if (error) std::rethrow_exception(error);
}

}  // namespace trimkit::mesh
