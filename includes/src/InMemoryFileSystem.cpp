// SPDX-License-Identifier: Apache-2.0
// Files held in a map, for tests and tools that build sources on the fly.
#include "varc/includes/FileSystem.h"

namespace varc::includes {

InMemoryFileSystem& InMemoryFileSystem::add(const std::string& path, std::string contents) {
    mFiles[normalizePath(path)] = std::move(contents);
    return *this;
}

std::optional<std::string> InMemoryFileSystem::read(const std::string& path) const {
    auto it = mFiles.find(normalizePath(path));
    if (it == mFiles.end()) return std::nullopt;
    return it->second;
}

bool InMemoryFileSystem::isFile(const std::string& path) const {
    return mFiles.count(normalizePath(path)) > 0;
}

std::vector<std::string> InMemoryFileSystem::fileNames(const std::string& dir) const {
    std::string folder = dir.empty() ? "" : normalizePath(dir);
    if (folder == ".") folder.clear();
    std::vector<std::string> names;
    for (const auto& [path, contents] : mFiles) {
        if (parentPath(path) == folder) names.push_back(path.substr(folder.empty() ? 0 : folder.size() + 1));
    }
    return names;  // std::map keeps them sorted
}

}  // namespace varc::includes
