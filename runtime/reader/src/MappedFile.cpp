// SPDX-License-Identifier: Apache-2.0
// A read-only memory mapping of a whole file, unmapped on destruction (move-only).
#include "MappedFile.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

namespace varc::reader::detail {

namespace {

Error ioError(const std::string& what, const std::string& path, int error) {
    return makeError(ErrorCode::IoError, what + " '" + path + "': " + std::strerror(error));
}

}  // namespace

MappedFile::MappedFile(MappedFile&& other) noexcept
    : mData(std::exchange(other.mData, nullptr)), mSize(std::exchange(other.mSize, 0)) {}

MappedFile& MappedFile::operator=(MappedFile&& other) noexcept {
    if (this != &other) {
        reset();
        mData = std::exchange(other.mData, nullptr);
        mSize = std::exchange(other.mSize, 0);
    }
    return *this;
}

MappedFile::~MappedFile() { reset(); }

void MappedFile::reset() {
    if (mData != nullptr) ::munmap(const_cast<std::byte*>(mData), mSize);
    mData = nullptr;
    mSize = 0;
}

Result<MappedFile> MappedFile::map(const std::string& path) {
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) return ioError("cannot open", path, errno);
    struct stat info {};
    if (::fstat(fd, &info) != 0) {
        int error = errno;
        ::close(fd);
        return ioError("cannot stat", path, error);
    }
    MappedFile file;
    if (info.st_size > 0) {
        auto size = static_cast<size_t>(info.st_size);
        // MAP_POPULATE: open() reads every byte anyway (checksums), and one batched fault of the
        // whole file is far cheaper than a page fault per 4 KiB.
        void* data = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
        if (data == MAP_FAILED) {
            int error = errno;
            ::close(fd);
            return ioError("cannot map", path, error);
        }
        file.mData = static_cast<const std::byte*>(data);
        file.mSize = size;
    }
    ::close(fd);
    return file;
}

}  // namespace varc::reader::detail
