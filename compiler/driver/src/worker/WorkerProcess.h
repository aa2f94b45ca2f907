// SPDX-License-Identifier: Apache-2.0
// One optimiser worker: a child process spawned with posix_spawn and the socket to it.
#pragma once

#include <sys/types.h>

#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace varc::driver::detail {

class WorkerProcess {
public:
    // Spawns `|executable| |command|` with one end of a socket pair as its standard input
    // (and nothing else of ours open). posix_spawn, not fork: the build is multi-threaded, and
    // a forked child of a threaded process may not run library code. nullptr and |error| set
    // when it cannot be spawned.
    static std::unique_ptr<WorkerProcess> spawn(const std::string& executable,
                                                std::string_view command, std::string& error);
    // Closes the socket, which ends an idle worker, and reaps it.
    ~WorkerProcess();
    WorkerProcess(const WorkerProcess&) = delete;
    WorkerProcess& operator=(const WorkerProcess&) = delete;

    // Sends |request| and returns the answer, or nullopt with |failure| saying what became of
    // the worker ("was killed by signal SIGSEGV (Segmentation fault)", "did not answer within
    // 60 s and was killed"). After a failure the worker is gone (killed and reaped): drop it.
    std::optional<std::string> exchange(std::string_view request, int timeoutMs,
                                        std::string& failure);

private:
    WorkerProcess(pid_t pid, int fd) : mPid(pid), mFd(fd) {}
    // Kills and reaps the worker; returns how it ended.
    std::string reap();

    pid_t mPid;
    int mFd;
};

// "was killed by signal SIGSEGV (Segmentation fault)", "exited with status 2": a waitpid status.
std::string describeWaitStatus(int status);

}  // namespace varc::driver::detail
