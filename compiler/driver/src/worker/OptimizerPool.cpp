// SPDX-License-Identifier: Apache-2.0
// The pool of optimiser workers: take one, send one request, give it back (or drop it if dead).
#include "varc/driver/OptimizerPool.h"

#include <filesystem>
#include <system_error>

#include "WorkerProcess.h"
#include "varc/driver/OptimizerWorker.h"
#include "varc/driver/WorkerProtocol.h"

namespace varc::driver {

OptimizerPool::OptimizerPool(std::string executable, int timeoutMs)
    : mExecutable(std::move(executable)), mTimeoutMs(timeoutMs) {}

OptimizerPool::~OptimizerPool() = default;

std::unique_ptr<detail::WorkerProcess> OptimizerPool::take(std::string& error) {
    {
        std::lock_guard<std::mutex> lock(mMutex);
        if (!mIdle.empty()) {
            std::unique_ptr<detail::WorkerProcess> worker = std::move(mIdle.back());
            mIdle.pop_back();
            return worker;
        }
        ++mSpawned;
    }
    return detail::WorkerProcess::spawn(mExecutable, kOptimizerWorkerCommand, error);
}

void OptimizerPool::giveBack(std::unique_ptr<detail::WorkerProcess> worker) {
    std::lock_guard<std::mutex> lock(mMutex);
    mIdle.push_back(std::move(worker));
}

IsolatedOutcome OptimizerPool::optimize(const std::vector<uint32_t>& spirv,
                                        OptimizationLevel level) {
    IsolatedOutcome result;
    std::string error;
    std::unique_ptr<detail::WorkerProcess> worker = take(error);
    if (!worker) {
        result.failure = "could not be started: " + error;
        return result;
    }
    std::optional<std::string> answer =
        worker->exchange(encodeRequest({level, spirv}), mTimeoutMs, result.failure);
    if (!answer) return result;  // |worker| is reaped already; dropping it closes nothing more
    result.outcome = decodeOutcome(*answer);
    if (!result.outcome) {
        result.failure = "sent a malformed answer";
        return result;  // dropped: a worker that answers garbage is not trusted again
    }
    giveBack(std::move(worker));
    return result;
}

size_t OptimizerPool::spawnedCount() const {
    std::lock_guard<std::mutex> lock(mMutex);
    return mSpawned;
}

std::string currentExecutablePath() {
    // The link itself, not its target: exec'ing it runs the very file this process runs, even
    // once a rebuild has replaced or deleted it at its path (the target then reads "(deleted)").
    std::error_code error;
    return std::filesystem::exists("/proc/self/exe", error) ? "/proc/self/exe" : std::string();
}

}  // namespace varc::driver
