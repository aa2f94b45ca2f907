// SPDX-License-Identifier: Apache-2.0
// glslang in-process: preprocess and compile one program stage to SPIR-V.
#include "varc/driver/GlslangFrontend.h"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <glslang/build_info.h>

#include <memory>
#include <mutex>

#include "varc/driver/GlslLegacyPreamble.h"
#include "varc/variants/PassKeywords.h"

namespace varc::driver {

namespace {

EShLanguage toGlslangStage(Stage stage) {
    switch (stage) {
        case Stage::Vertex:
            return EShLangVertex;
        case Stage::Fragment:
            return EShLangFragment;
        case Stage::Geometry:
            return EShLangGeometry;
        case Stage::Hull:
            return EShLangTessControl;
        case Stage::Domain:
            return EShLangTessEvaluation;
    }
    return EShLangVertex;
}

bool isHlsl(const FrontendInput& input) {
    return input.language != shaderlab::ProgramLanguage::Glsl;
}

EShMessages messagesFor(const FrontendInput& input) {
    int messages = EShMsgSpvRules | EShMsgVulkanRules;
    if (isHlsl(input))
        messages |= EShMsgReadHlsl | EShMsgHlslDX9Compatible | EShMsgHlslLegalization;
    return static_cast<EShMessages>(messages);
}

// One descriptor set per stage, numbered like the stage slots (docs/SHADER_ABI.md §1).
uint32_t descriptorSetOfStage(Stage stage) { return static_cast<uint32_t>(stageIndex(stage)); }

// Default version for sources without `#version`: HLSL ignores it; see GlslLegacyPreamble.h.
int defaultVersion(const FrontendInput& input) { return isHlsl(input) ? 100 : kLegacyGlslVersion; }

// A TShader configured for |input|; |text| and |preamble| must outlive it.
std::unique_ptr<glslang::TShader> makeShader(const FrontendInput& input, const char* const* text,
                                             const int* length, const std::string& preamble) {
    EShLanguage stage = toGlslangStage(input.stage);
    auto shader = std::make_unique<glslang::TShader>(stage);
    static const char* const kNames[] = {"program"};
    shader->setStringsWithLengthsAndNames(text, length, kNames, 1);
    shader->setPreamble(preamble.c_str());
    shader->setEntryPoint(std::string(input.entryPoint).c_str());
    shader->setSourceEntryPoint(std::string(input.entryPoint).c_str());
    glslang::EShSource source = isHlsl(input) ? glslang::EShSourceHlsl : glslang::EShSourceGlsl;
    shader->setEnvInput(source, stage, glslang::EShClientVulkan, 100);
    if (!isHlsl(input)) shader->setEnvInputVulkanRulesRelaxed();
    shader->setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_0);
    shader->setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_0);
    if (isHlsl(input)) shader->setEnvTargetHlslFunctionality1();
    shader->setAutoMapBindings(true);
    shader->setAutoMapLocations(true);
    // One descriptor set per stage (docs/SHADER_ABI.md §1): bindings are numbered per program, so
    // two stages sharing set 0 would give one binding two meanings in a pipeline layout.
    shader->setResourceSetBinding({std::to_string(descriptorSetOfStage(input.stage))});
    // Unity's D3D11-style textures (`Texture2D t; SamplerState sampler_t; t.Sample(sampler_t, uv)`)
    // become combined image samplers named after the texture, and the samplers go: every
    // texture is one COMBINED_IMAGE_SAMPLER binding, whichever way it was declared
    // (docs/SHADER_ABI.md §3).
    if (isHlsl(input))
        shader->setTextureSamplerTransformMode(EShTexSampTransUpgradeTextureRemoveSampler);
    return shader;
}

}  // namespace

void initializeGlslang() {
    static std::once_flag once;
    std::call_once(once, [] { glslang::InitializeProcess(); });
}

PreprocessOutput preprocessProgram(const FrontendInput& input) {
    initializeGlslang();
    const char* text = input.text.data();
    int length = static_cast<int>(input.text.size());
    std::string preamble(input.preamble);
    auto shader = makeShader(input, &text, &length, preamble);
    PreprocessOutput output;
    glslang::TShader::ForbidIncluder noIncludes;  // includes were spliced by varc already
    output.ok = shader->preprocess(GetDefaultResources(), defaultVersion(input), ENoProfile, false,
                                   false, messagesFor(input), &output.text, noIncludes);
    output.log = shader->getInfoLog();
    return output;
}

CompileOutput compileProgram(const FrontendInput& input) {
    initializeGlslang();
    const char* text = input.text.data();
    int length = static_cast<int>(input.text.size());
    std::string preamble(input.preamble);
    auto shader = makeShader(input, &text, &length, preamble);
    CompileOutput output;
    EShMessages messages = messagesFor(input);
    if (!shader->parse(GetDefaultResources(), defaultVersion(input), false, messages)) {
        output.log = shader->getInfoLog();
        return output;
    }
    glslang::TProgram program;
    program.addShader(shader.get());
    if (!program.link(messages) || !program.mapIO()) {
        output.log = std::string(shader->getInfoLog()) + program.getInfoLog();
        return output;
    }
    glslang::SpvOptions options;
    options.disableOptimizer = true;  // SPIRV-Tools runs afterwards with varc's -O level
    spv::SpvBuildLogger logger;
    glslang::GlslangToSpv(*program.getIntermediate(toGlslangStage(input.stage)), output.spirv,
                          &logger, &options);
    output.log = logger.getAllMessages();
    // glslang still emits a module when SPIR-V generation meets something it does not implement
    // (a matrix swizzle); that module is wrong, so it is a failure.
    output.ok =
        !output.spirv.empty() && output.log.find("Missing functionality") == std::string::npos;
    return output;
}

std::string glslangVersionString() {
    return std::to_string(GLSLANG_VERSION_MAJOR) + "." + std::to_string(GLSLANG_VERSION_MINOR) +
           "." + std::to_string(GLSLANG_VERSION_PATCH);
}

}  // namespace varc::driver
