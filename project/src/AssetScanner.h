// SPDX-License-Identifier: Apache-2.0
// Finds the asset files loadProject reads, in the project and in the shader source roots.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "LoadContext.h"

namespace varc::project {

// A folder the project reads assets from.
struct AssetArea {
    std::filesystem::path folder;  // on disk, inside the project
    std::string assetPrefix;       // "Assets", "Packages/<name>", or "" (an AssetFolder root)
    // The same folder in each shader source root; only `.shader` files are taken from these.
    std::vector<std::filesystem::path> overlayFolders;
};

struct ScannedFile {
    std::string assetPath;  // prefix + path inside the area, with '/' separators
    std::filesystem::path file;
};

// Each list sorted by asset path.
struct AssetFiles {
    std::vector<ScannedFile> shaders;          // `*.shader`: the project's, else an overlay's
    std::vector<ScannedFile> shaderMetas;      // `*.shader.meta`; asset path without ".meta"
    std::vector<ScannedFile> materials;        // `*.mat`
    std::vector<ScannedFile> collections;      // `*.shadervariants`
    std::vector<ScannedFile> collectionMetas;  // `*.shadervariants.meta`; path without ".meta"
};

// True for the names Unity does not import: `.*`, `*~`, `cvs` and `*.tmp`.
bool isUnityIgnoredName(const std::string& name);

// Walks |areas| (symbolic links to folders are not followed, so a link cycle cannot hang the
// walk); folders Unity ignores are skipped unless |includeIgnored|. A folder that cannot be
// read is warned about and the walk goes on without it.
AssetFiles scanAssets(const std::vector<AssetArea>& areas, bool includeIgnored,
                      LoadContext& context);

// The `guid:` line of the .meta file |metaFile|, or "" after a warning when it has none.
std::string readMetaGuid(const std::filesystem::path& metaFile, LoadContext& context);

}  // namespace varc::project
