// SPDX-License-Identifier: Apache-2.0
// Writes a file so that readers see either the old contents or the complete new contents.
#include "varc/core/AtomicFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cerrno>
#include <cstring>
#include <filesystem>

namespace varc {

namespace {

Error ioError(const std::string& what, const std::string& path, int error) {
    return makeError(ErrorCode::IoError, what + " '" + path + "': " + std::strerror(error));
}

// Writes all of |contents| to |fd|; false with errno set on failure.
bool writeAll(int fd, std::string_view contents) {
    while (!contents.empty()) {
        ssize_t written = ::write(fd, contents.data(), contents.size());
        if (written < 0 && errno == EINTR) continue;
        if (written <= 0) return false;
        contents.remove_prefix(static_cast<size_t>(written));
    }
    return true;
}

// The temporaries of writes in progress, for the termination-signal handler. Lock-free slots of
// plain pointers, so the handler can read them (async-signal-safe); a write that finds every
// slot taken simply goes untracked.
constexpr size_t kTrackedTemporaries = 256;
std::array<std::atomic<const char*>, kTrackedTemporaries> gTemporaries{};

class TrackedTemporary {
public:
    explicit TrackedTemporary(const std::string& path) {
        for (size_t i = 0; i < kTrackedTemporaries; ++i) {
            const char* expected = nullptr;
            if (gTemporaries[i].compare_exchange_strong(expected, path.c_str())) {
                mSlot = i;
                return;
            }
        }
    }
    ~TrackedTemporary() {
        if (mSlot < kTrackedTemporaries) gTemporaries[mSlot].store(nullptr);
    }
    TrackedTemporary(const TrackedTemporary&) = delete;
    TrackedTemporary& operator=(const TrackedTemporary&) = delete;

private:
    size_t mSlot = kTrackedTemporaries;
};

void removeTemporariesAndReraise(int signal) {
    for (std::atomic<const char*>& slot : gTemporaries) {
        if (const char* path = slot.load()) ::unlink(path);
    }
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

// A sibling of |path| no other writer uses: same directory, so the rename cannot cross file
// systems; the process id and a per-process counter keep two processes, and two threads of one
// process, from sharing it (O_EXCL makes sure).
std::string temporaryPathFor(const std::string& path) {
    static std::atomic<uint64_t> counter{0};
    return path + ".tmp." + std::to_string(::getpid()) + "." + std::to_string(counter++);
}

// Writes into an existing file that is not a regular file (a character device such as
// /dev/null, a FIFO): varc never replaces or removes those, it only writes to them.
Status writeInPlace(const std::string& path, std::string_view contents) {
    int fd = ::open(path.c_str(), O_WRONLY | O_CLOEXEC);
    if (fd < 0) return ioError("cannot open", path, errno);
    bool written = writeAll(fd, contents);
    int error = errno;
    if (::close(fd) != 0 && written) return ioError("cannot write", path, errno);
    if (!written) return ioError("cannot write", path, error);
    return Ok{};
}

// Writes |contents| to a new temporary file next to |path| and renames it over |path|.
Status replaceRegularFile(const std::string& path, std::string_view contents,
                          Durability durability) {
    const std::string temp = temporaryPathFor(path);
    TrackedTemporary tracked(temp);
    int fd = ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) {
        const int error = errno;  // before any allocation below
        return makeError(ErrorCode::IoError, "cannot write '" + path + "' (its temporary '" + temp +
                                                 "' cannot be created): " + std::strerror(error));
    }
    bool written =
        writeAll(fd, contents) && (durability == Durability::Unsynced || ::fsync(fd) == 0);
    int error = errno;
    if (::close(fd) != 0 && written) {
        written = false;
        error = errno;
    }
    if (!written) {
        ::unlink(temp.c_str());
        return ioError("cannot write", temp, error);
    }
    if (::rename(temp.c_str(), path.c_str()) != 0) {
        error = errno;
        ::unlink(temp.c_str());
        return ioError("cannot rename to", path, error);
    }
    return Ok{};
}

}  // namespace

void removeTemporariesOnTerminationSignals() {
    struct sigaction action {};
    action.sa_handler = removeTemporariesAndReraise;
    sigemptyset(&action.sa_mask);
    for (int signal : {SIGINT, SIGTERM, SIGHUP}) ::sigaction(signal, &action, nullptr);
}

Status writeFileAtomically(const std::string& path, std::string_view contents,
                           Durability durability) {
    // A symbolic link stays a link: the file it names is replaced.
    std::error_code ignored;
    std::string target = path;
    if (std::filesystem::is_symlink(path, ignored)) {
        std::filesystem::path resolved = std::filesystem::weakly_canonical(path, ignored);
        if (!ignored) target = resolved.string();
    }
    struct stat info {};
    if (::stat(target.c_str(), &info) == 0) {
        if (S_ISDIR(info.st_mode))
            return makeError(ErrorCode::IoError, "cannot write '" + path + "': it is a directory");
        if (!S_ISREG(info.st_mode)) return writeInPlace(target, contents);
    }
    return replaceRegularFile(target, contents, durability);
}

}  // namespace varc
