// SPDX-License-Identifier: Apache-2.0
// Shaders by name, for the references between shaders: `UsePass "Shader/PASS"` and `Fallback`.
#include "varc/frontend/ShaderCatalog.h"

#include "varc/core/Diagnostic.h"
#include "varc/shaderlab/ShaderLabParser.h"

namespace varc::frontend {

namespace {

constexpr std::string_view kLegacyPrefix = "Legacy Shaders/";

}  // namespace

ShaderCatalog::ShaderCatalog(const includes::FileSystem& fileSystem,
                             includes::SourceMap& sourceMap, std::vector<std::string> inputFiles,
                             std::vector<std::string> searchFiles, std::string builtinDir)
    : mFileSystem(fileSystem), mSourceMap(sourceMap) {
    mGroups[0].files = std::move(inputFiles);
    mGroups[1].files = std::move(searchFiles);
    if (builtinDir.empty()) return;
    mBuiltinShaderDir = includes::joinPath(builtinDir, "fallback");
}

void ShaderCatalog::parse(Group& group) {
    group.parsed = true;
    if (&group == &mGroups[2] && !mBuiltinShaderDir.empty()) {
        for (const std::string& name : mFileSystem.fileNames(mBuiltinShaderDir)) {
            if (name.ends_with(".shader")) {
                group.files.push_back(includes::joinPath(mBuiltinShaderDir, name));
            }
        }
    }
    for (const std::string& path : group.files) {
        std::optional<FileId> file = mSourceMap.find(path);
        if (!file) {
            std::optional<std::string> text = mFileSystem.read(path);
            if (!text) continue;
            file = mSourceMap.addFile(path, std::move(*text));
        }
        DiagnosticList ignored;  // reported when the file is loaded as an input
        auto shader = shaderlab::parseShaderLab(mSourceMap.contents(*file), *file, ignored);
        if (shader) group.shaders.push_back(std::move(*shader));
    }
}

const shaderlab::ShaderFile* ShaderCatalog::findInGroups(std::string_view name) {
    for (Group& group : mGroups) {
        if (!group.parsed) parse(group);
        for (const shaderlab::ShaderFile& shader : group.shaders) {
            if (shader.name == name) return &shader;
        }
    }
    return nullptr;
}

const shaderlab::ShaderFile* ShaderCatalog::find(std::string_view name) {
    if (const shaderlab::ShaderFile* shader = findInGroups(name)) return shader;
    if (name.starts_with(kLegacyPrefix)) return nullptr;
    return findInGroups(std::string(kLegacyPrefix) + std::string(name));
}

}  // namespace varc::frontend
