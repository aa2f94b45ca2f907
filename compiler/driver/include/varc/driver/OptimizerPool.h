// SPDX-License-Identifier: Apache-2.0
// Runs validateAndOptimize in persistent worker processes, so a crash or hang in SPIRV-Tools
// costs one program an error instead of ending (or stalling) the build.
#pragma once

#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "varc/driver/SpirvOptimizer.h"

namespace varc::driver {

namespace detail {
class WorkerProcess;
}

// What an isolated optimisation gave: the worker's outcome, or why there is none.
struct IsolatedOutcome {
    std::optional<OptimizeOutcome> outcome;
    // Without an outcome: what became of the worker, as a phrase that follows "the optimiser
    // worker" ("was killed by signal SIGSEGV (Segmentation fault)", "did not answer within 60 s
    // and was killed", "could not be started: ...").
    std::string failure;
};

// Idle workers wait in the pool; a thread takes one (spawning it when none is idle, so there are
// at most as many as threads optimising at once), sends one request and puts it back. A worker
// that died is reaped and dropped; the next request spawns a fresh one. Thread-safe.
class OptimizerPool {
public:
    // |executable| is run as `executable __optimizer-worker` (OptimizerWorker.h): varc itself.
    // |timeoutMs| bounds each request (a hung worker is killed).
    OptimizerPool(std::string executable, int timeoutMs);
    ~OptimizerPool();  // ends and reaps the idle workers
    OptimizerPool(const OptimizerPool&) = delete;
    OptimizerPool& operator=(const OptimizerPool&) = delete;

    IsolatedOutcome optimize(const std::vector<uint32_t>& spirv, OptimizationLevel level);

    size_t spawnedCount() const;  // workers started so far (a respawn counts again)

private:
    std::unique_ptr<detail::WorkerProcess> take(std::string& error);
    void giveBack(std::unique_ptr<detail::WorkerProcess> worker);

    std::string mExecutable;
    int mTimeoutMs;
    mutable std::mutex mMutex;
    std::vector<std::unique_ptr<detail::WorkerProcess>> mIdle;
    size_t mSpawned = 0;
};

// A path that runs the running executable ("/proc/self/exe"), or empty when there is none.
std::string currentExecutablePath();

}  // namespace varc::driver
