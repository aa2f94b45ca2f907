// SPDX-License-Identifier: Apache-2.0
// ShaderVariantCollection objects: `m_Shaders` entries of {first: shader, second: {variants}}.
#include "VariantCollectionReader.h"

#include "UnityYaml.h"

namespace varc::project {

namespace {

std::vector<CollectedVariant> readVariants(const YAML::Node& second,
                                           const std::filesystem::path& file,
                                           LoadContext& context) {
    std::vector<CollectedVariant> variants;
    auto list = field(second, "variants");
    if (!list || !list->IsSequence()) return variants;
    for (const YAML::Node& entry : *list) {
        auto passType = field(entry, "passType");
        auto value = passType ? integerValue(*passType) : std::nullopt;
        if (!value) {
            auto [line, column] = positionOf(entry);
            context.warn(file, line, column, "variant without a readable passType; skipped");
            continue;
        }
        CollectedVariant variant;
        variant.passType = static_cast<int>(*value);
        if (auto keywords = field(entry, "keywords")) variant.keywords = keywordList(*keywords);
        variants.push_back(std::move(variant));
    }
    return variants;
}

}  // namespace

std::optional<ShaderVariantCollection> readVariantCollection(const std::filesystem::path& file,
                                                             const std::string& assetPath,
                                                             const std::string& guid,
                                                             const ShaderGuidIndex& shaders,
                                                             LoadContext& context) {
    auto text = context.readText(file);
    if (!text) return std::nullopt;
    auto documents = parseUnityYaml(*text, file, context);
    if (!documents) return std::nullopt;
    auto object = findObject(*documents, "ShaderVariantCollection");
    if (!object) {
        context.warn(file, "no ShaderVariantCollection object in the file; skipped");
        return std::nullopt;
    }
    ShaderVariantCollection collection;
    collection.path = assetPath;
    collection.file = file;
    collection.guid = guid;
    if (auto name = field(*object, "m_Name")) collection.name = scalarText(*name).value_or("");
    auto entries = field(*object, "m_Shaders");
    if (!entries || !entries->IsSequence()) return collection;
    for (const YAML::Node& entry : *entries) {
        auto first = field(entry, "first");
        ReferenceSite site{file, positionOf(first ? *first : entry), "collection entry"};
        CollectedShader shader;
        shader.shader =
            shaders.resolve(first ? assetReference(*first) : std::nullopt, site, context);
        if (auto second = field(entry, "second")) {
            shader.variants = readVariants(*second, file, context);
        }
        collection.shaders.push_back(std::move(shader));
    }
    return collection;
}

}  // namespace varc::project
