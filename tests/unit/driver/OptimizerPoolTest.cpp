// SPDX-License-Identifier: Apache-2.0
// OptimizerPool with workers that are not varc: each way a worker can fail is an answer, not a
// crash of the caller. (The CLI cases build-optimizer-* cover the real worker, its crashes
// and the deadline.)
#include <gtest/gtest.h>

#include "varc/driver/OptimizerPool.h"

namespace varc::driver {
namespace {

const std::vector<uint32_t> kModule = {0x07230203u, 0x00010000u, 0, 1, 0};

TEST(OptimizerPool, AWorkerThatCannotStartIsAFailure) {
    OptimizerPool pool("/nonexistent/varc", 1000);
    IsolatedOutcome result = pool.optimize(kModule, OptimizationLevel::Performance);
    EXPECT_FALSE(result.outcome);
    EXPECT_NE(result.failure.find("could not be started"), std::string::npos) << result.failure;
}

TEST(OptimizerPool, AWorkerThatExitsIsReapedAndNamed) {
    OptimizerPool pool("/bin/true", 5000);
    IsolatedOutcome result = pool.optimize(kModule, OptimizationLevel::None);
    EXPECT_FALSE(result.outcome);
    EXPECT_EQ(result.failure, "exited with status 0");
    // The dead worker is not reused: the next request spawns another.
    pool.optimize(kModule, OptimizationLevel::None);
    EXPECT_EQ(pool.spawnedCount(), 2u);
}

}  // namespace
}  // namespace varc::driver
