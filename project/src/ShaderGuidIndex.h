// SPDX-License-Identifier: Apache-2.0
// Shader GUIDs (from `.shader.meta` files) to asset paths, and resolving shader references.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "LoadContext.h"
#include "varc/project/AssetReference.h"

namespace varc::project {

// Where a reference was written, for warnings: the file, 1-based line/column (0 = unknown) and
// what holds it ("material 'Rock'", "always-included shader").
struct ReferenceSite {
    std::filesystem::path file;
    std::pair<uint32_t, uint32_t> position;
    std::string holder;
};

class ShaderGuidIndex {
public:
    // Records |guid| -> |assetPath|; a GUID seen again keeps the first path (callers add in
    // sorted order) and the duplicate is reported at |metaFile|.
    void add(const std::string& guid, const std::string& assetPath,
             const std::filesystem::path& metaFile, LoadContext& context);
    const std::string* find(const std::string& guid) const;

    // Classifies |reference| (nullopt = absent or unreadable) and warns, at |site|, about a
    // missing reference and a GUID no `.meta` defines. Built-in references are not checked
    // here: BuiltinShaders.h names them.
    ShaderReference resolve(const std::optional<AssetReference>& reference,
                            const ReferenceSite& site, LoadContext& context) const;

private:
    std::map<std::string, std::string> mPaths;
};

}  // namespace varc::project
