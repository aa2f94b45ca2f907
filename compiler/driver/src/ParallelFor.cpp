// SPDX-License-Identifier: Apache-2.0
// A minimal worker pool: runs an indexed job over [0, count) on N threads.
#include "varc/driver/ParallelFor.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace varc::driver {

namespace {

// The first exception any worker threw; once set, workers claim no more jobs.
class FirstFailure {
public:
    void record(std::exception_ptr failure) {
        std::lock_guard<std::mutex> lock(mMutex);
        if (!mFailure) mFailure = std::move(failure);
        mFailed.store(true);
    }
    bool failed() const { return mFailed.load(); }
    void rethrow() const {
        if (mFailure) std::rethrow_exception(mFailure);
    }

private:
    std::mutex mMutex;
    std::exception_ptr mFailure;
    std::atomic<bool> mFailed{false};
};

}  // namespace

void parallelFor(size_t count, unsigned threads, const std::function<void(size_t)>& job,
                 bool firstAlone) {
    size_t start = 0;
    if (firstAlone && count > 0) {
        job(0);
        start = 1;
    }
    std::atomic<size_t> next{start};
    FirstFailure failure;
    // A job that throws must not end the process (an exception leaving a std::thread calls
    // std::terminate): it is caught, the pool stops claiming jobs, and it is rethrown here once
    // every thread has joined.
    auto worker = [&] {
        try {
            for (size_t i = next.fetch_add(1); i < count && !failure.failed();
                 i = next.fetch_add(1))
                job(i);
        } catch (...) {
            failure.record(std::current_exception());
        }
    };
    size_t helpers =
        std::min<size_t>(threads > 0 ? threads - 1 : 0, count - std::min(count, start));
    std::vector<std::thread> pool;
    pool.reserve(helpers);
    for (size_t i = 0; i < helpers; ++i) pool.emplace_back(worker);
    worker();
    for (std::thread& thread : pool) thread.join();
    failure.rethrow();
}

unsigned defaultThreadCount() { return std::max(1u, std::thread::hardware_concurrency()); }

}  // namespace varc::driver
