// SPDX-License-Identifier: Apache-2.0
// Finds a Unity project's packages: embedded ones, `manifest.json` entries, Library/PackageCache.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "LoadContext.h"
#include "varc/project/Project.h"

namespace varc::project {

struct PackageSearch {
    std::vector<ProjectPackage> packages;  // sorted by name
    std::vector<std::string> notOnDisk;    // manifest names without a folder, sorted
};

// The packages of the project at |root|:
//   1. every folder under `Packages/` (Unity ignore rules apply unless |includeIgnored|), named
//      by its package.json `name`, or by the folder name when it has none (copies of projects
//      often leave package.json out; Unity itself would skip such a folder);
//   2. each `Packages/manifest.json` dependency not embedded: `file:<path>` folders (relative
//      to Packages/), else `Library/PackageCache/<name>@<version>`, else the first
//      `<name>@*` there (Unity 6 suffixes a hash, not the version).
// Unreadable JSON is warned about; manifest entries with no folder (built-in modules, a fresh
// clone without Library/) are listed in notOnDisk without a warning.
PackageSearch locatePackages(const std::filesystem::path& root, bool includeIgnored,
                             LoadContext& context);

}  // namespace varc::project
