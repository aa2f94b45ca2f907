// SPDX-License-Identifier: Apache-2.0
// Writes a file so that readers see either the old contents or the complete new contents.
#include "varc/core/AtomicFile.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace varc {

namespace {

Error ioError(const std::string& what, const std::string& path) {
    return makeError(ErrorCode::IoError, what + " '" + path + "': " + std::strerror(errno));
}

// A unique sibling of |path|: same directory, so the rename cannot cross file systems.
std::string temporaryPathFor(const std::string& path) {
    return path + ".tmp." + std::to_string(::getpid());
}

}  // namespace

Status writeFileAtomically(const std::string& path, std::string_view contents) {
    std::string temp = temporaryPathFor(path);
    std::FILE* file = std::fopen(temp.c_str(), "wb");
    if (!file) return ioError("cannot create", temp);
    bool written = std::fwrite(contents.data(), 1, contents.size(), file) == contents.size();
    written = (std::fflush(file) == 0) && written;
    written = (::fsync(::fileno(file)) == 0) && written;
    if (std::fclose(file) != 0 || !written) {
        Error error = ioError("cannot write", temp);
        std::remove(temp.c_str());
        return error;
    }
    if (std::rename(temp.c_str(), path.c_str()) != 0) {
        Error error = ioError("cannot rename to", path);
        std::remove(temp.c_str());
        return error;
    }
    return Ok{};
}

}  // namespace varc
