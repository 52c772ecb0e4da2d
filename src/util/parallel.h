// Running a loop body for every index on all cores.  The body writes its results to slots of
// its own index, so what a loop computes never depends on how many threads ran it.
#pragma once

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace mirage {

/// The number of worker threads for `threads` (0: one per core), at least 1.
inline int worker_count(int threads = 0) {
    if (threads > 0) return threads;
    return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}

/// Runs body(i) for every i in [0, n), in any order, on `threads` threads (0: all cores).
/// Indices are handed out in blocks of `grain` to keep the shared counter cold.
template <class Body>
void parallel_for(long n, const Body& body, int threads = 0, long grain = 64) {
    if (n <= 0) return;
    grain = std::max(1L, grain);
    const int workers =
        static_cast<int>(std::min<long>(worker_count(threads), (n + grain - 1) / grain));
    std::atomic<long> next{0};
    auto work = [&] {
        for (long begin = next.fetch_add(grain); begin < n; begin = next.fetch_add(grain)) {
            const long end = std::min(n, begin + grain);
            for (long i = begin; i < end; ++i) body(i);
        }
    };
    std::vector<std::thread> pool;
    pool.reserve(static_cast<size_t>(std::max(0, workers - 1)));
    for (int t = 1; t < workers; ++t) pool.emplace_back(work);
    work();
    for (auto& t : pool) t.join();
}

}  // namespace mirage
