// SPDX-License-Identifier: Apache-2.0
// parallelFor runs every index exactly once, and job 0 alone first when asked.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
#include <vector>

#include "varc/driver/ParallelFor.h"

namespace varc::driver {
namespace {

TEST(ParallelFor, RunsEveryIndexExactlyOnce) {
    for (unsigned threads : {1u, 2u, 7u}) {
        std::vector<std::atomic<int>> hits(1000);
        parallelFor(hits.size(), threads, [&](size_t i) { hits[i].fetch_add(1); });
        for (size_t i = 0; i < hits.size(); ++i) ASSERT_EQ(hits[i].load(), 1) << i;
    }
}

TEST(ParallelFor, FirstJobCompletesBeforeOthersStart) {
    std::atomic<bool> firstDone{false};
    std::atomic<int> startedEarly{0};
    parallelFor(
        64, 4,
        [&](size_t i) {
            if (i == 0) {
                firstDone.store(true);
            } else if (!firstDone.load()) {
                startedEarly.fetch_add(1);
            }
        },
        /*firstAlone=*/true);
    EXPECT_EQ(startedEarly.load(), 0);
}

TEST(ParallelFor, HandlesZeroItems) {
    int calls = 0;
    parallelFor(
        0, 4, [&](size_t) { ++calls; }, true);
    EXPECT_EQ(calls, 0);
}

// A throwing job (glslang can throw; std::bad_alloc can happen anywhere) reaches the caller as
// an exception, whichever thread ran it, and later jobs are not started.
// Jobs after the failing one wait until it has thrown and then take a millisecond, so that
// "stops the rest" does not depend on how the machine schedules the threads: the pool would
// have to miss the failure for seconds to run all 10000 (it was flaky when the jobs were
// instant and a loaded machine let three threads run them all before the failure was seen).
TEST(ParallelFor, AJobThatThrowsReachesTheCallerAndStopsTheRest) {
    for (unsigned threads : {1u, 4u}) {
        std::atomic<size_t> ran{0};
        std::atomic<bool> thrown{false};
        try {
            parallelFor(10000, threads, [&](size_t i) {
                ran.fetch_add(1);
                if (i == 3) {
                    thrown.store(true);
                    throw std::runtime_error("job 3 failed");
                }
                if (i < 3) return;
                while (!thrown.load()) std::this_thread::yield();
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
            });
            ADD_FAILURE() << "no exception with " << threads << " threads";
        } catch (const std::runtime_error& e) {
            EXPECT_STREQ(e.what(), "job 3 failed");
        }
        EXPECT_LT(ran.load(), 10000u) << threads << " threads";
    }
}

}  // namespace
}  // namespace varc::driver
