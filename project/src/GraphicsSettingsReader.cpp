// SPDX-License-Identifier: Apache-2.0
// GraphicsSettings: always-included shaders, preloaded collections, stripping fields.
#include "GraphicsSettingsReader.h"

#include "UnityYaml.h"

namespace varc::project {

namespace {

std::optional<int> intField(const YAML::Node& object, const char* key) {
    auto value = field(object, key);
    if (!value) return std::nullopt;
    auto number = integerValue(*value);
    if (!number) return std::nullopt;
    return static_cast<int>(*number);
}

std::optional<bool> flagField(const YAML::Node& object, const char* key) {
    auto number = intField(object, key);
    if (!number) return std::nullopt;
    return *number != 0;
}

void readStripping(const YAML::Node& object, GraphicsSettings& settings) {
    settings.serializedVersion = intField(object, "serializedVersion");
    settings.lightmapStripping = intField(object, "m_LightmapStripping");
    settings.fogStripping = intField(object, "m_FogStripping");
    settings.instancingStripping = intField(object, "m_InstancingStripping");
    settings.brgStripping = intField(object, "m_BrgStripping");
    settings.lightmapKeepPlain = flagField(object, "m_LightmapKeepPlain");
    settings.lightmapKeepDirCombined = flagField(object, "m_LightmapKeepDirCombined");
    settings.lightmapKeepDynamicPlain = flagField(object, "m_LightmapKeepDynamicPlain");
    settings.lightmapKeepDynamicDirCombined = flagField(object, "m_LightmapKeepDynamicDirCombined");
    settings.lightmapKeepShadowMask = flagField(object, "m_LightmapKeepShadowMask");
    settings.lightmapKeepSubtractive = flagField(object, "m_LightmapKeepSubtractive");
    settings.lightmapKeepDirSeparate = flagField(object, "m_LightmapKeepDirSeparate");
    settings.lightmapKeepDynamicDirSeparate = flagField(object, "m_LightmapKeepDynamicDirSeparate");
    settings.fogKeepLinear = flagField(object, "m_FogKeepLinear");
    settings.fogKeepExp = flagField(object, "m_FogKeepExp");
    settings.fogKeepExp2 = flagField(object, "m_FogKeepExp2");
}

void readShaderLists(const YAML::Node& object, const std::filesystem::path& file,
                     const ShaderGuidIndex& shaders,
                     const std::map<std::string, std::string>& collectionPaths,
                     GraphicsSettings& settings, LoadContext& context) {
    if (auto list = field(object, "m_AlwaysIncludedShaders"); list && list->IsSequence()) {
        for (const YAML::Node& entry : *list) {
            ReferenceSite site{file, positionOf(entry), "always-included shader"};
            settings.alwaysIncluded.push_back(
                shaders.resolve(assetReference(entry), site, context));
        }
    }
    if (auto list = field(object, "m_PreloadedShaders"); list && list->IsSequence()) {
        for (const YAML::Node& entry : *list) {
            auto reference = assetReference(entry);
            if (!reference) {
                auto [line, column] = positionOf(entry);
                context.warn(file, line, column, "unreadable preloaded collection; skipped");
                continue;
            }
            PreloadedCollection preloaded{*reference, {}};
            auto found = collectionPaths.find(reference->guid);
            if (found != collectionPaths.end()) preloaded.collectionPath = found->second;
            settings.preloaded.push_back(std::move(preloaded));
        }
    }
}

}  // namespace

std::optional<GraphicsSettings> readGraphicsSettings(
    const std::filesystem::path& file, const ShaderGuidIndex& shaders,
    const std::map<std::string, std::string>& collectionPaths, LoadContext& context) {
    auto text = context.readText(file);
    if (!text) return std::nullopt;
    auto documents = parseUnityYaml(*text, file, context);
    if (!documents) return std::nullopt;
    auto object = findObject(*documents, "GraphicsSettings");
    if (!object) {
        context.warn(file, "no GraphicsSettings object in the file; not read");
        return std::nullopt;
    }
    GraphicsSettings settings;
    settings.path = file.string();
    readStripping(*object, settings);
    readShaderLists(*object, file, shaders, collectionPaths, settings, context);
    if (auto pipeline = field(*object, "m_CustomRenderPipeline")) {
        auto reference = assetReference(*pipeline);
        if (reference && !reference->isNull() && reference->fileId != 0) {
            settings.customRenderPipeline = *reference;
        }
    }
    return settings;
}

}  // namespace varc::project
