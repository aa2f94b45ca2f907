// SPDX-License-Identifier: Apache-2.0
// Reads a whole file with POSIX calls: no exceptions, clear reasons.
#include "varc/core/FileRead.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace varc {

namespace {

Error readError(const std::string& what, const std::string& path, const std::string& reason) {
    return makeError(ErrorCode::IoError, what + " '" + path + "': " + reason);
}

// Closes the descriptor on every path out of readFile.
class FileDescriptor {
public:
    explicit FileDescriptor(int fd) : mFd(fd) {}
    ~FileDescriptor() {
        if (mFd >= 0) ::close(mFd);
    }
    FileDescriptor(const FileDescriptor&) = delete;
    FileDescriptor& operator=(const FileDescriptor&) = delete;
    int get() const { return mFd; }

private:
    int mFd;
};

}  // namespace

Result<std::string> readFile(const std::string& path, size_t maxBytes) {
    FileDescriptor fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
    if (fd.get() < 0) return readError("cannot open", path, std::strerror(errno));
    struct stat info {};
    if (::fstat(fd.get(), &info) != 0) return readError("cannot read", path, std::strerror(errno));
    if (S_ISDIR(info.st_mode)) return readError("cannot read", path, "it is a directory");
    if (!S_ISREG(info.st_mode)) return readError("cannot read", path, "it is not a regular file");
    if (static_cast<uint64_t>(info.st_size) > maxBytes) {
        return readError("cannot read", path,
                         "it has " + std::to_string(info.st_size) + " bytes; at most " +
                             std::to_string(maxBytes) + " are read");
    }
    std::string contents;
    contents.reserve(static_cast<size_t>(info.st_size));
    char buffer[1 << 16];
    for (;;) {
        ssize_t got = ::read(fd.get(), buffer, sizeof buffer);
        if (got < 0 && errno == EINTR) continue;
        if (got < 0) return readError("cannot read", path, std::strerror(errno));
        if (got == 0) break;
        if (contents.size() + static_cast<size_t>(got) > maxBytes) {
            return readError("cannot read", path,
                             "it has more than " + std::to_string(maxBytes) + " bytes");
        }
        contents.append(buffer, static_cast<size_t>(got));
    }
    return contents;
}

}  // namespace varc
