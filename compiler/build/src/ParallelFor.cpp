// SPDX-License-Identifier: Apache-2.0
// A minimal worker pool: runs an indexed job over [0, count) on N threads.
#include "varc/build/ParallelFor.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace varc::compiler {

void parallelFor(size_t count, unsigned threads, const std::function<void(size_t)>& job,
                 bool firstAlone) {
    size_t start = 0;
    if (firstAlone && count > 0) {
        job(0);
        start = 1;
    }
    std::atomic<size_t> next{start};
    auto worker = [&] {
        for (size_t i = next.fetch_add(1); i < count; i = next.fetch_add(1)) job(i);
    };
    size_t helpers = std::min<size_t>(threads > 0 ? threads - 1 : 0, count - std::min(count, start));
    std::vector<std::thread> pool;
    pool.reserve(helpers);
    for (size_t i = 0; i < helpers; ++i) pool.emplace_back(worker);
    worker();
    for (std::thread& thread : pool) thread.join();
}

unsigned defaultThreadCount() { return std::max(1u, std::thread::hardware_concurrency()); }

}  // namespace varc::compiler
