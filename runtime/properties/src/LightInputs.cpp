// SPDX-License-Identifier: Apache-2.0
// LightInputs: the light inputs a shader's programs read, from the pack's reflection.
#include "varc/properties/LightInputs.h"

#include <algorithm>
#include <set>

#include "varc/core/AsciiCase.h"
#include "varc/core/Stage.h"
#include "varc/reader/PassView.h"
#include "varc/reader/VariantView.h"

namespace varc::properties {

const std::vector<std::string_view>& lightInputNames() {
    // Every name varc's renderer fills from the scene's lights, grouped as varc's built-in
    // includes declare them (shaders/builtin). Reflection lists a uniform block whole when a
    // program reads any member, so each block is listed whole. Sorted (std::sort below).
    static const std::vector<std::string_view> kNames = [] {
        std::vector<std::string_view> names{
            // UnityShaderVariables.cginc, block UnityLighting: the pixel light of this draw (the
            // main directional light in ForwardBase, one light per ForwardAdd draw).
            // _LightMatrix0 is a macro for unity_WorldToLight there; GLSL shaders and older
            // HLSL ones declare it themselves, so the reflection may record either name.
            "_WorldSpaceLightPos0", "_LightColor0", "_LightPositionRange", "_LightProjectionParams",
            "unity_WorldToLight", "_LightMatrix0", "unity_OcclusionMaskSelector",
            // Block UnityShadows: the pixel light's real-time shadows.
            "unity_ShadowSplitSpheres", "unity_ShadowSplitSqRadii", "unity_LightShadowBias",
            "_LightSplitsNear", "_LightSplitsFar", "unity_WorldToShadow", "_LightShadowData",
            "unity_ShadowFadeCenterAndType", "_ShadowMapTexture_TexelSize",
            // Block UnityProbes: light probes (ambient and the lights Unity bakes into SH).
            "unity_SHAr", "unity_SHAg", "unity_SHAb", "unity_SHBr", "unity_SHBg", "unity_SHBb",
            "unity_SHC", "unity_ProbesOcclusion",
            // Block UnityVertexLights: the four per-vertex lights and the Vertex pass's eight.
            "unity_4LightPosX0", "unity_4LightPosY0", "unity_4LightPosZ0", "unity_4LightAtten0",
            "unity_LightColor", "unity_LightPosition", "unity_LightAtten", "unity_SpotDirection",
            // Per-object light lists (UnityInstancing / the renderer's light indices).
            "unity_4LightIndices0", "unity_4LightIndices1", "unity_LightIndicesOffsetAndCount",
            // AutoLight.cginc / UnityDeferredLibrary.cginc textures: falloff and cookie, the
            // screen-space shadow mask.
            "_LightTexture0", "_LightTextureB0", "_ShadowMapTexture",
            // UnityDeferredLibrary.cginc, block UnityDeferredLight: the deferred light pass's
            // light, and the G-buffer it reads; _LightBuffer, the light buffer a legacy
            // deferred (PrepassFinal) pass reads.
            "_LightDir", "_LightPos", "_LightColor", "_CameraGBufferTexture*", "_LightBuffer"};
        std::sort(names.begin(), names.end());
        return names;
    }();
    return kNames;
}

bool isLightInput(std::string_view name) {
    // Unity names a texture's separate sampler "sampler" + the texture's name.
    if (name.size() > 7 && name.starts_with("sampler") && isLightInput(name.substr(7))) return true;
    for (std::string_view entry : lightInputNames()) {
        if (entry.ends_with('*')) {
            if (name.starts_with(entry.substr(0, entry.size() - 1))) return true;
        } else if (name == entry) {
            return true;
        }
    }
    return false;
}

std::vector<std::string> lightInputsRead(const pack::ProgramReflection& program) {
    std::set<std::string> read;
    auto members = [&read](const std::vector<pack::BlockMember>& list) {
        for (const pack::BlockMember& member : list)
            if (isLightInput(member.name)) read.insert(member.name);
    };
    for (const pack::UniformBlock& block : program.uniformBlocks) members(block.members);
    for (const pack::PushConstantBlock& block : program.pushConstants) members(block.members);
    for (const pack::ResourceBinding& resource : program.resources)
        if (isLightInput(resource.name)) read.insert(resource.name);
    return {read.begin(), read.end()};
}

bool drawnPerLight(std::string_view lightMode) {
    return equalsIgnoreAsciiCase(lightMode, "ForwardAdd");
}

LightInputReport lightInputsOf(const std::vector<PassReflection>& passes) {
    std::set<std::string> read;
    LightInputReport report;
    for (const PassReflection& pass : passes) {
        size_t without = 0;
        std::string first;
        for (const VariantReflection& variant : pass.variants) {
            bool reads = false;
            for (const pack::ProgramReflection& program : variant.programs) {
                for (std::string& name : lightInputsRead(program)) {
                    read.insert(std::move(name));
                    reads = true;
                }
            }
            if (reads) continue;
            if (without++ == 0) first = variant.description;
        }
        if (without == 0 || !drawnPerLight(pass.lightMode)) continue;
        report.findings.push_back(pass.lightMode + " variant " + first +
                                  " reads no light input, yet Unity draws it once per light (" +
                                  std::to_string(without) + " of " +
                                  std::to_string(pass.variants.size()) + " variants)");
    }
    report.read.assign(read.begin(), read.end());
    return report;
}

std::vector<PassReflection> litPassReflections(const reader::ShaderView& shader) {
    std::vector<PassReflection> passes;
    for (size_t p = 0; p < shader.passCount(); ++p) {
        const std::optional<reader::PassView> pass = shader.pass(p);
        if (!pass) continue;
        const std::string_view lightMode = pass->lightMode();
        if (!equalsIgnoreAsciiCase(lightMode, "ForwardBase") && !drawnPerLight(lightMode)) continue;
        PassReflection reflection{std::string(lightMode), {}};
        for (size_t v = 0; v < pass->variantCount(); ++v) {
            const reader::VariantView variant = pass->variant(v);
            VariantReflection programs{variant.describe(), {}};
            for (Stage stage : kStages)
                if (std::optional<reader::ProgramView> program = variant.program(stage))
                    programs.programs.push_back(program->reflection());
            reflection.variants.push_back(std::move(programs));
        }
        passes.push_back(std::move(reflection));
    }
    return passes;
}

LightModelDecision decideLightModel(const LightInputReport& inputs, bool responds) {
    LightModelDecision decision;
    decision.notLit = !inputs.lit() && !responds;
    if (!inputs.lit() && responds)
        decision.litFailures.push_back(
            "light response without a light input: a key light changes the image, but no "
            "program of the ForwardBase and ForwardAdd passes reads any light input "
            "(varc::properties::lightInputNames()): it reads the light through a path the list "
            "misses");
    for (const std::string& finding : inputs.findings) decision.litFailures.push_back(finding);
    return decision;
}

}  // namespace varc::properties
