// SPDX-License-Identifier: Apache-2.0
// The real file system, read through std::filesystem without letting exceptions escape.
#include <filesystem>

#include "varc/core/FileRead.h"
#include "varc/includes/FileSystem.h"

namespace varc::includes {

std::optional<std::string> DiskFileSystem::read(const std::string& path) const {
    if (!isFile(path)) return std::nullopt;
    Result<std::string> contents = readFile(normalizePath(path));
    if (!contents) return std::nullopt;
    return std::move(*contents);
}

bool DiskFileSystem::isFile(const std::string& path) const {
    if (path.empty()) return false;
    std::error_code error;
    return std::filesystem::is_regular_file(std::filesystem::path(normalizePath(path)), error);
}

}  // namespace varc::includes
