// SPDX-License-Identifier: Apache-2.0
// Reads the Material objects of one `.mat` file.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "LoadContext.h"
#include "ShaderGuidIndex.h"
#include "varc/project/Material.h"

namespace varc::project {

// The materials of |file| (asset path |assetPath|), one per `Material:` document, in document
// order. A binary or malformed file gives a warning and no material (Unity cannot use it as
// text either); a file without a Material object gives a warning. Missing fields are warned
// about and left at their defaults.
std::vector<Material> readMaterials(const std::filesystem::path& file, const std::string& assetPath,
                                    const ShaderGuidIndex& shaders, LoadContext& context);

}  // namespace varc::project
