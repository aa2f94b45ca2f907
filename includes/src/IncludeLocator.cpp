// SPDX-License-Identifier: Apache-2.0
// Finds the file an #include names: including file's directory, -I dirs, built-in dir.
#include "IncludeLocator.h"

#include <algorithm>

#include "varc/core/AsciiCase.h"

namespace varc::includes {

bool IncludeLocator::exists(const std::string& path) const {
    return mSourceMap.find(path).has_value() || mFileSystem.isFile(path);
}

std::optional<std::string> IncludeLocator::locate(const std::string& name,
                                                  const std::string& includerDir,
                                                  std::vector<std::string>& searched,
                                                  bool* caseDiffers) const {
    std::string portable = name;
    std::replace(portable.begin(), portable.end(), '\\', '/');
    searched.clear();
    if (caseDiffers) *caseDiffers = false;
    if (portable.empty()) return std::nullopt;
    if (portable.front() == '/') {
        std::string path = normalizePath(portable);
        return exists(path) ? std::optional<std::string>(path) : std::nullopt;
    }
    std::vector<std::string> dirs{includerDir};
    dirs.insert(dirs.end(), mOptions.includeDirs.begin(), mOptions.includeDirs.end());
    if (!mOptions.builtinDir.empty()) dirs.push_back(mOptions.builtinDir);
    std::vector<std::string> tried;
    for (const std::string& dir : dirs) {
        std::string shown = dir.empty() ? "." : normalizePath(dir);
        if (std::find(searched.begin(), searched.end(), shown) != searched.end()) continue;
        searched.push_back(shown);
        tried.push_back(dir);
        std::string path = joinPath(dir, portable);
        if (exists(path)) return path;
    }
    if (auto path = findFromProjectRoot(portable, includerDir, searched)) return path;
    for (const std::string& dir : tried) {
        if (auto path = findIgnoringCase(dir, portable)) {
            if (caseDiffers) *caseDiffers = true;
            return path;
        }
    }
    return std::nullopt;
}

// Unity resolves "Assets/Foo/Bar.cginc" from the project's root folder, the one that holds
// Assets/ (and Packages/).
std::optional<std::string> IncludeLocator::findFromProjectRoot(
    const std::string& name, const std::string& includerDir,
    std::vector<std::string>& searched) const {
    if (!name.starts_with("Assets/") && !name.starts_with("Packages/")) return std::nullopt;
    for (const IncludeOptions::VirtualRoot& root : mOptions.virtualRoots) {
        if (!name.starts_with(root.prefix + "/")) continue;
        searched.push_back(normalizePath(root.folder) + " (" + root.prefix + ")");
        std::string path = joinPath(root.folder, name.substr(root.prefix.size() + 1));
        if (exists(path)) return path;
    }
    if (!mOptions.projectRoot.empty()) {
        searched.push_back(normalizePath(mOptions.projectRoot) + " (project root)");
        std::string path = joinPath(mOptions.projectRoot, name);
        return exists(path) ? std::optional<std::string>(path) : std::nullopt;
    }
    searched.push_back("the folders above " + (includerDir.empty() ? "." : includerDir));
    std::string dir = normalizePath(includerDir.empty() ? "." : includerDir);
    for (int depth = 0; depth < 64; ++depth) {  // bounded: a path has finitely many parents
        std::string path = joinPath(dir == "." ? "" : dir, name);
        if (exists(path)) return path;
        if (dir == "." || dir == "/" || dir.ends_with("..")) break;
        std::string parent = parentPath(dir);
        dir = parent.empty() ? "." : parent;
    }
    return std::nullopt;
}

// The file |name| in |dir| whose last path component matches ignoring ASCII case (folders must
// match exactly); the first in sorted order when several do.
std::optional<std::string> IncludeLocator::findIgnoringCase(const std::string& dir,
                                                            const std::string& name) const {
    std::string path = joinPath(dir, name);
    std::string folder = parentPath(path);
    std::string file = path.substr(folder.empty() ? 0 : folder.size() + 1);
    if (folder == "/") file = path.substr(1);
    for (const std::string& candidate : mFileSystem.fileNames(folder)) {
        if (equalsIgnoreAsciiCase(candidate, file)) return joinPath(folder, candidate);
    }
    return std::nullopt;
}

}  // namespace varc::includes
