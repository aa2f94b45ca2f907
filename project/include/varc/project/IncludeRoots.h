// SPDX-License-Identifier: Apache-2.0
// Where `#include "Assets/..."` and `#include "Packages/<name>/..."` of a Unity project live.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace varc::project {

// Virtual prefixes of Unity asset paths mapped to folders on disk. Each prefix may have several
// folders, tried in order: the project's own first, then the shader source roots
// (LoadOptions::shaderSourceRoots) at the same relative path.
struct IncludeRoots {
    // Folders that hold the project's `Assets/` folder (the project root, then the overlays).
    std::vector<std::filesystem::path> projectRoots;
    // "Packages/<package name>" -> package folders (embedded, local or Library/PackageCache).
    std::map<std::string, std::vector<std::filesystem::path>> packages;

    // The file |includePath| names, e.g. "Packages/com.example.fx/Shaders/Fx.cginc" or
    // "Assets/Shaders/Common.cginc": the first existing regular file; nullopt when the prefix is
    // unknown or no folder has the file.
    std::optional<std::filesystem::path> resolve(std::string_view includePath) const;
};

}  // namespace varc::project
