// SPDX-License-Identifier: Apache-2.0
// Finds the file an #include names: including file's directory, -I dirs, built-in dir.
#include "IncludeLocator.h"

#include <algorithm>

namespace varc::includes {

bool IncludeLocator::exists(const std::string& path) const {
    return mSourceMap.find(path).has_value() || mFileSystem.isFile(path);
}

std::optional<std::string> IncludeLocator::locate(const std::string& name,
                                                  const std::string& includerDir,
                                                  std::vector<std::string>& searched) const {
    std::string portable = name;
    std::replace(portable.begin(), portable.end(), '\\', '/');
    searched.clear();
    if (portable.empty()) return std::nullopt;
    if (portable.front() == '/') {
        std::string path = normalizePath(portable);
        return exists(path) ? std::optional<std::string>(path) : std::nullopt;
    }
    std::vector<std::string> dirs{includerDir};
    dirs.insert(dirs.end(), mOptions.includeDirs.begin(), mOptions.includeDirs.end());
    if (!mOptions.builtinDir.empty()) dirs.push_back(mOptions.builtinDir);
    for (const std::string& dir : dirs) {
        std::string shown = dir.empty() ? "." : normalizePath(dir);
        if (std::find(searched.begin(), searched.end(), shown) != searched.end()) continue;
        searched.push_back(shown);
        std::string path = joinPath(dir, portable);
        if (exists(path)) return path;
    }
    return std::nullopt;
}

}  // namespace varc::includes
