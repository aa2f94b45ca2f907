// SPDX-License-Identifier: Apache-2.0
// Material objects: shader reference, the two keyword serialisations, instancing.
#include "MaterialReader.h"

#include "UnityYaml.h"

namespace varc::project {

namespace {

void readKeywords(const YAML::Node& object, Material& material) {
    if (auto legacy = field(object, "m_ShaderKeywords")) {
        material.hasLegacyField = true;
        material.legacyKeywords = keywordList(*legacy);
    }
    if (auto valid = field(object, "m_ValidKeywords")) {
        material.hasListFields = true;
        material.validKeywords = keywordList(*valid);
    }
    if (auto invalid = field(object, "m_InvalidKeywords")) {
        material.hasListFields = true;
        material.invalidKeywords = keywordList(*invalid);
    }
}

Material readMaterial(const YAML::Node& object, const std::filesystem::path& file,
                      const std::string& assetPath, const ShaderGuidIndex& shaders,
                      LoadContext& context) {
    Material material;
    material.path = assetPath;
    material.file = file;
    if (auto name = field(object, "m_Name")) material.name = scalarText(*name).value_or("");
    std::string holder = "material '" + material.name + "'";
    auto shaderField = field(object, "m_Shader");
    ReferenceSite site{file, positionOf(shaderField ? *shaderField : object), holder};
    material.shader =
        shaders.resolve(shaderField ? assetReference(*shaderField) : std::nullopt, site, context);
    readKeywords(object, material);
    if (!material.hasLegacyField && !material.hasListFields) {
        auto [line, column] = positionOf(object);
        context.warn(file, line, column,
                     holder +
                         " has neither m_ShaderKeywords nor m_ValidKeywords; read as no "
                         "keywords");
    }
    if (auto instancing = field(object, "m_EnableInstancingVariants")) {
        material.enableInstancingVariants = integerValue(*instancing).value_or(0) != 0;
    }
    return material;
}

}  // namespace

std::vector<Material> readMaterials(const std::filesystem::path& file, const std::string& assetPath,
                                    const ShaderGuidIndex& shaders, LoadContext& context) {
    std::vector<Material> materials;
    auto text = context.readText(file);
    if (!text) return materials;
    auto documents = parseUnityYaml(*text, file, context);
    if (!documents) return materials;
    for (const YAML::Node& document : *documents) {
        if (auto object = field(document, "Material"); object && object->IsMap()) {
            materials.push_back(readMaterial(*object, file, assetPath, shaders, context));
        }
    }
    if (materials.empty()) context.warn(file, "no Material object in the file; skipped");
    return materials;
}

}  // namespace varc::project
