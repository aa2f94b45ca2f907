// SPDX-License-Identifier: Apache-2.0
// Shader GUID lookup and the classification of shader references, with their warnings.
#include "ShaderGuidIndex.h"

namespace varc::project {

void ShaderGuidIndex::add(const std::string& guid, const std::string& assetPath,
                          const std::filesystem::path& metaFile, LoadContext& context) {
    auto [existing, inserted] = mPaths.emplace(guid, assetPath);
    if (!inserted && existing->second != assetPath) {
        context.warn(metaFile, "GUID " + guid + " is also the GUID of '" + existing->second +
                                   "'; references to it mean that shader");
    }
}

const std::string* ShaderGuidIndex::find(const std::string& guid) const {
    auto found = mPaths.find(guid);
    return found == mPaths.end() ? nullptr : &found->second;
}

ShaderReference ShaderGuidIndex::resolve(const std::optional<AssetReference>& reference,
                                         const ReferenceSite& site, LoadContext& context) const {
    ShaderReference result;
    auto [line, column] = site.position;
    if (!reference) {
        context.warn(site.file, line, column,
                     site.holder +
                         " has no readable shader reference; Unity draws it with "
                         "the error shader");
        return result;
    }
    result.asset = *reference;
    if (reference->fileId == 0) {
        context.warn(site.file, line, column,
                     site.holder +
                         " names no shader ({fileID: 0}); Unity draws it with the "
                         "error shader");
        return result;
    }
    if (reference->isBuiltin()) {
        result.kind = ShaderReferenceKind::Builtin;
        return result;
    }
    if (const std::string* path = find(reference->guid)) {
        result.kind = ShaderReferenceKind::Project;
        result.shaderPath = *path;
        return result;
    }
    result.kind = ShaderReferenceKind::UnknownGuid;
    context.warn(site.file, line, column,
                 site.holder + ": shader GUID " + reference->guid +
                     " is defined by no .shader.meta of the project; Unity draws it with the "
                     "error shader");
    return result;
}

}  // namespace varc::project
