// SPDX-License-Identifier: Apache-2.0
// Material keyword views and the names of shader reference kinds.
#include "varc/project/Material.h"

#include <algorithm>

namespace varc::project {

namespace {

std::vector<std::string> sortedUnion(std::initializer_list<const std::vector<std::string>*> lists) {
    std::vector<std::string> all;
    for (const auto* list : lists) all.insert(all.end(), list->begin(), list->end());
    std::sort(all.begin(), all.end());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    return all;
}

}  // namespace

const char* shaderReferenceKindName(ShaderReferenceKind kind) {
    switch (kind) {
        case ShaderReferenceKind::Project:
            return "project";
        case ShaderReferenceKind::UnknownGuid:
            return "unknown-guid";
        case ShaderReferenceKind::Builtin:
            return "builtin";
        case ShaderReferenceKind::Missing:
            return "missing";
    }
    return "missing";
}

KeywordForm Material::keywordForm() const {
    if (hasLegacyField && hasListFields) return KeywordForm::Both;
    if (hasLegacyField) return KeywordForm::LegacyString;
    if (hasListFields) return KeywordForm::Lists;
    return KeywordForm::None;
}

std::vector<std::string> Material::enabledKeywords() const {
    return sortedUnion({&legacyKeywords, &validKeywords});
}

std::vector<std::string> Material::keywordsIncludingInvalid() const {
    return sortedUnion({&legacyKeywords, &validKeywords, &invalidKeywords});
}

}  // namespace varc::project
