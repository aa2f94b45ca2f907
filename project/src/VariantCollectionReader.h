// SPDX-License-Identifier: Apache-2.0
// Reads one ShaderVariantCollection (`.shadervariants`) file.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "LoadContext.h"
#include "ShaderGuidIndex.h"
#include "varc/project/ShaderVariantCollection.h"

namespace varc::project {

// The collection in |file| (asset path |assetPath|, GUID |guid| from its .meta), or nullopt
// after a warning when the file is binary, malformed or has no ShaderVariantCollection object.
// An entry without a readable passType is warned about and skipped.
std::optional<ShaderVariantCollection> readVariantCollection(const std::filesystem::path& file,
                                                             const std::string& assetPath,
                                                             const std::string& guid,
                                                             const ShaderGuidIndex& shaders,
                                                             LoadContext& context);

}  // namespace varc::project
