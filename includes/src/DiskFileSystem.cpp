// SPDX-License-Identifier: Apache-2.0
// The real file system, read through std::filesystem without letting exceptions escape.
#include <algorithm>
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

std::vector<std::string> DiskFileSystem::fileNames(const std::string& dir) const {
    std::vector<std::string> names;
    std::error_code error;
    std::filesystem::path folder(dir.empty() ? "." : normalizePath(dir));
    for (std::filesystem::directory_iterator it(folder, error), end; !error && it != end;
         it.increment(error)) {
        std::error_code typeError;
        if (it->is_regular_file(typeError)) names.push_back(it->path().filename().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace varc::includes
