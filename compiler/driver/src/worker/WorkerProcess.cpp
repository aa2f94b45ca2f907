// SPDX-License-Identifier: Apache-2.0
// Spawning, talking to and reaping one worker process.
#include "WorkerProcess.h"

#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "varc/driver/WorkerProtocol.h"

extern char** environ;

namespace varc::driver::detail {

std::unique_ptr<WorkerProcess> WorkerProcess::spawn(const std::string& executable,
                                                    std::string_view command, std::string& error) {
    int fds[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0) {
        error = std::string("cannot create a socket pair: ") + std::strerror(errno);
        return nullptr;
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, fds[1], STDIN_FILENO);  // clears FD_CLOEXEC
    // Descriptors other threads opened without O_CLOEXEC (streams, lock files) stay ours.
    posix_spawn_file_actions_addclosefrom_np(&actions, STDERR_FILENO + 1);
    std::string commandText(command);
    char* argv[] = {const_cast<char*>(executable.c_str()), commandText.data(), nullptr};
    pid_t pid = 0;
    int spawned = ::posix_spawn(&pid, executable.c_str(), &actions, nullptr, argv, environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[1]);
    if (spawned != 0) {
        ::close(fds[0]);
        error = "cannot start " + executable + ": " + std::strerror(spawned);
        return nullptr;
    }
    return std::unique_ptr<WorkerProcess>(new WorkerProcess(pid, fds[0]));
}

WorkerProcess::~WorkerProcess() {
    if (mFd >= 0) ::close(mFd);
    if (mPid > 0) {
        int status = 0;
        while (::waitpid(mPid, &status, 0) < 0 && errno == EINTR) {
        }
    }
}

std::optional<std::string> WorkerProcess::exchange(std::string_view request, int timeoutMs,
                                                   std::string& failure) {
    if (writeFrame(mFd, request)) {
        Frame answer = readFrame(mFd, timeoutMs);
        if (answer.status == FrameStatus::Ok) return std::move(answer.bytes);
        if (answer.status == FrameStatus::TimedOut) {
            reap();
            failure = "did not answer within " + std::to_string((timeoutMs + 999) / 1000) +
                      " s and was killed";
            return std::nullopt;
        }
    }
    // The socket ended (the worker died), or the answer was not a frame: the worker is done
    // for either way. SIGKILL cannot change the status of a worker that has already died (its
    // socket closes only once its exit status is set), and ends one that has gone astray.
    failure = reap();
    return std::nullopt;
}

std::string WorkerProcess::reap() {
    ::kill(mPid, SIGKILL);
    ::close(mFd);
    mFd = -1;
    int status = 0;
    pid_t reaped;
    while ((reaped = ::waitpid(mPid, &status, 0)) < 0 && errno == EINTR) {
    }
    mPid = -1;
    if (reaped < 0) return std::string("could not be waited for: ") + std::strerror(errno);
    return describeWaitStatus(status);
}

std::string describeWaitStatus(int status) {
    if (WIFSIGNALED(status)) {
        const int signal = WTERMSIG(status);
        const char* abbrev = ::sigabbrev_np(signal);
        std::string name = abbrev ? std::string("SIG") + abbrev : std::to_string(signal);
        return "was killed by signal " + name + " (" + ::strsignal(signal) + ")";
    }
    if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
    return "ended with wait status " + std::to_string(status);
}

}  // namespace varc::driver::detail
