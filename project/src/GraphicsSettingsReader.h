// SPDX-License-Identifier: Apache-2.0
// Reads `ProjectSettings/GraphicsSettings.asset`.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "LoadContext.h"
#include "ShaderGuidIndex.h"
#include "varc/project/GraphicsSettings.h"

namespace varc::project {

// The settings in |file|, or nullopt after a warning when it is binary (old projects), malformed
// or has no GraphicsSettings object. |collectionPaths| maps `.shadervariants` GUIDs to asset
// paths for the preloaded collections.
std::optional<GraphicsSettings> readGraphicsSettings(
    const std::filesystem::path& file, const ShaderGuidIndex& shaders,
    const std::map<std::string, std::string>& collectionPaths, LoadContext& context);

}  // namespace varc::project
