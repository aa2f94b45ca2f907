// SPDX-License-Identifier: Apache-2.0
// One material (`.mat`) as the project reader found it: its shader and its keywords.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "varc/project/AssetReference.h"

namespace varc::project {

// Which keyword fields the file has: Unity up to 2021.2 writes `m_ShaderKeywords` (one
// space-separated string), later versions the lists `m_ValidKeywords` / `m_InvalidKeywords`.
enum class KeywordForm { None, LegacyString, Lists, Both };

struct Material {
    std::string path;            // asset path, e.g. "Assets/Materials/Rock.mat"
    std::filesystem::path file;  // the file on disk
    std::string name;            // `m_Name`
    ShaderReference shader;      // `m_Shader`, resolved against the project's `.meta` GUIDs
    // Each list in file order; tokens made only of underscores (a lone `_` occurs in real files)
    // are not keywords and are dropped.
    std::vector<std::string> legacyKeywords;   // `m_ShaderKeywords`
    std::vector<std::string> validKeywords;    // `m_ValidKeywords`
    std::vector<std::string> invalidKeywords;  // `m_InvalidKeywords`: not declared when saved
    bool hasLegacyField = false;               // `m_ShaderKeywords` present (even empty)
    bool hasListFields = false;                // `m_ValidKeywords` or `m_InvalidKeywords` present
    bool enableInstancingVariants = false;     // `m_EnableInstancingVariants: 1`

    KeywordForm keywordForm() const;
    // legacy ∪ valid, sorted and unique: what the material enables.
    std::vector<std::string> enabledKeywords() const;
    // enabledKeywords() ∪ invalid, sorted and unique: the set to intersect with a shader's current
    // declarations, since an edited shader may declare a keyword that was invalid when saved.
    std::vector<std::string> keywordsIncludingInvalid() const;
};

}  // namespace varc::project
