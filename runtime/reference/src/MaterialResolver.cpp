// SPDX-License-Identifier: Apache-2.0
// resolveMaterial: a scene material -> the parameters of its reference model, and its caster.
#include "MaterialResolver.h"

#include <algorithm>
#include <variant>

#include "varc/reference/Shading.h"

namespace varc::reference {
namespace {

using scene::PropertyValue;

Status readColorProperty(const PropertyValue& value, const std::string& name, glm::vec4& out) {
    if (const auto* v = std::get_if<glm::vec4>(&value)) {
        out = *v;
        return Ok{};
    }
    return makeError(ErrorCode::InvalidInput, "material property " + name + ": expected a colour");
}

Status readFloatProperty(const PropertyValue& value, const std::string& name, float& out) {
    if (const auto* v = std::get_if<float>(&value)) {
        out = *v;
        return Ok{};
    }
    return makeError(ErrorCode::InvalidInput, "material property " + name + ": expected a number");
}

// Standard's caster (UnityStandardShadow.cginc) under the material's shader_feature keywords:
// _ALPHATEST_ON clips at _Cutoff; _ALPHABLEND_ON and _ALPHAPREMULTIPLY_ON dither, the latter
// with alpha raised to 1 - oneMinusReflectivity + alpha * oneMinusReflectivity (linear colour
// space: oneMinusReflectivity = 0.96 - 0.96 * _Metallic). Without them it is opaque. The
// three are one shader_feature: InvalidInput when the material names more than one.
Status applyStandardCasterKeywords(const std::vector<std::string>& keywords, MaterialParams& p) {
    auto has = [&](const char* k) {
        return std::find(keywords.begin(), keywords.end(), k) != keywords.end();
    };
    const int named =
        int{has("_ALPHATEST_ON")} + int{has("_ALPHABLEND_ON")} + int{has("_ALPHAPREMULTIPLY_ON")};
    if (named > 1) {
        return makeError(ErrorCode::InvalidInput,
                         "material keywords: at most one of _ALPHATEST_ON, _ALPHABLEND_ON and "
                         "_ALPHAPREMULTIPLY_ON (one shader_feature)");
    }
    if (has("_ALPHATEST_ON")) {
        p.casterAlphaTest = true;
    } else if (has("_ALPHABLEND_ON")) {
        p.casterDither = true;
    } else if (has("_ALPHAPREMULTIPLY_ON")) {
        p.casterDither = true;
        const float oneMinusReflectivity = 0.96f - 0.96f * p.metallic;
        p.casterAlphaScale = oneMinusReflectivity;
        p.casterAlphaBias = 1.0f - oneMinusReflectivity;
    }
    return Ok{};
}

}  // namespace

// How |m|'s object draws into the shadow maps.
ShadowCaster casterOf(const MaterialParams& m, const ReferenceOptions& options) {
    ShadowCaster caster;
    caster.casts = m.castsShadows;
    caster.cullOff = m.casterCullOff;
    caster.alphaTest = m.casterAlphaTest && !options.ignoreCasterCutoff;
    caster.dither = m.casterDither;
    caster.alphaScale = m.casterAlphaScale;
    caster.alphaBias = m.casterAlphaBias;
    caster.cutoff = m.cutoff;
    caster.colorAlpha = m.color.a;
    caster.mainTexAlpha = m.mainTex.a;
    caster.mainTexture = m.mainTexture;
    caster.mainTexST = m.mainTexST;
    return caster;
}

Result<MaterialParams> resolveMaterial(const scene::Material& material) {
    MaterialParams p;
    std::string colorName = "_Color";
    const std::string model = scene::referenceModelOf(material);
    if (model == "seed000") {
        colorName = "_Tint";
        p.smoothness = 0.1f;
    } else if (model == "varc-forward") {
        p.model = ShaderModel::ForwardPbs;
        p.castsShadows = true;
        p.receivesAddShadows = true;
    } else if (model == "varc-simple-diffuse") {
        p.model = ShaderModel::SimpleDiffuse;
        p.castsShadows = true;
        p.receivesAddShadows = true;
        p.receivesBaseShadows = true;
    } else if (model == "varc-glsl-vertex-lights") {
        p.model = ShaderModel::GlslBlinnPhong;
    } else if (model == "seed001") {
        p.model = ShaderModel::Seed001Phong;
        p.shininess = 10.0f;
    } else if (model == "seed004") {
        p.model = ShaderModel::Seed004Diffuse;
        p.castsShadows = true;         // Fallback "VertexLit"
        p.receivesBaseShadows = true;  // multi_compile_fwdbase; its add pass has no shadow keywords
    } else if (model == "varc-caster" || model == "varc-caster-cutout" ||
               model == "varc-standard-caster") {
        p.model = ShaderModel::CasterOnly;
        p.castsShadows = true;
        p.casterCullOff = p.casterAlphaTest = model == "varc-caster-cutout";
    } else {
        return makeError(ErrorCode::NotFound,
                         "no reference model for shader '" + material.shader + "'" +
                             (model.empty() ? std::string() : " (reference '" + model + "')"));
    }
    for (const auto& [name, value] : material.properties) {
        Status status = Ok{};
        if (name == colorName) {
            status = readColorProperty(value, name, p.color);
        } else if (name == "_MainTex") {
            status = readColorTexture(value, name, p.mainTex, p.mainTexture);
        } else if (name == "_MainTex_ST") {
            status = readColorProperty(value, name, p.mainTexST);
        } else if (name == "_Metallic") {
            status = readFloatProperty(value, name, p.metallic);
        } else if (name == "_Smoothness") {
            status = readFloatProperty(value, name, p.smoothness);
        } else if (name == "_SpecColor") {
            glm::vec4 c;
            status = readColorProperty(value, name, c);
            p.specColor = glm::vec3(c);
        } else if (name == "_Shininess") {
            status = readFloatProperty(value, name, p.shininess);
        } else if (name == "_Cutoff") {
            status = readFloatProperty(value, name, p.cutoff);
        }
        if (!status) return status.error();
    }
    if (model == "varc-standard-caster") {
        if (Status keywords = applyStandardCasterKeywords(material.keywords, p); !keywords)
            return keywords.error();
    }
    return p;
}

}  // namespace varc::reference
