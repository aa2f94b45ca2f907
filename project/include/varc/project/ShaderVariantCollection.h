// SPDX-License-Identifier: Apache-2.0
// A ShaderVariantCollection (`.shadervariants`): per shader, the variants a project asks for.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "varc/project/AssetReference.h"

namespace varc::project {

struct CollectedVariant {
    int passType = 0;                   // Unity's PassType: 4 ForwardBase, 8 ShadowCaster, ...
    std::vector<std::string> keywords;  // in file order; empty = the no-keyword variant
};

struct CollectedShader {
    ShaderReference shader;
    std::vector<CollectedVariant> variants;  // in file order
};

struct ShaderVariantCollection {
    std::string path;                      // asset path, e.g. "Assets/Warmup.shadervariants"
    std::filesystem::path file;            // the file on disk
    std::string guid;                      // from its `.meta`; empty without one
    std::string name;                      // `m_Name`
    std::vector<CollectedShader> shaders;  // `m_Shaders`, in file order
};

}  // namespace varc::project
