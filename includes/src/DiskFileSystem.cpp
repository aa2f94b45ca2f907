// SPDX-License-Identifier: Apache-2.0
// The real file system, read through std::filesystem without letting exceptions escape.
#include <filesystem>
#include <fstream>
#include <iterator>

#include "varc/includes/FileSystem.h"

namespace varc::includes {

std::optional<std::string> DiskFileSystem::read(const std::string& path) const {
    if (!isFile(path)) return std::nullopt;
    std::ifstream in(std::filesystem::path(normalizePath(path)), std::ios::binary);
    if (!in) return std::nullopt;
    std::string contents{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (in.bad()) return std::nullopt;
    return contents;
}

bool DiskFileSystem::isFile(const std::string& path) const {
    if (path.empty()) return false;
    std::error_code error;
    return std::filesystem::is_regular_file(std::filesystem::path(normalizePath(path)), error);
}

}  // namespace varc::includes
