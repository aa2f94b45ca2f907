// SPDX-License-Identifier: Apache-2.0
// The macros varc defines before a program, as Unity does: API, target, pass, stage, keywords.
#include "varc/driver/PassDefines.h"

#include <algorithm>
#include <cctype>

#include "varc/core/AsciiCase.h"
#include "varc/driver/InstancingOptions.h"
#include "varc/variants/PassKeywords.h"

namespace varc::driver {

namespace {

const char* stageMacro(Stage stage) {
    switch (stage) {
        case Stage::Vertex:
            return "SHADER_STAGE_VERTEX";
        case Stage::Fragment:
            return "SHADER_STAGE_FRAGMENT";
        case Stage::Geometry:
            return "SHADER_STAGE_GEOMETRY";
        case Stage::Hull:
            return "SHADER_STAGE_HULL";
        case Stage::Domain:
            return "SHADER_STAGE_DOMAIN";
    }
    return nullptr;
}

// GLSLPROGRAM blocks hold every stage in one text, selected by VERTEX / FRAGMENT.
const char* glslStageMacro(Stage stage) {
    switch (stage) {
        case Stage::Vertex:
            return "VERTEX";
        case Stage::Fragment:
            return "FRAGMENT";
        case Stage::Geometry:
            return "GEOMETRY";
        default:
            return nullptr;
    }
}

}  // namespace

int shaderTargetNumber(std::string_view target) {
    if (target.empty()) return 25;
    size_t dot = target.find('.');
    if (dot == std::string_view::npos || dot == 0 || dot + 2 != target.size()) return -1;
    for (size_t i = 0; i < target.size(); ++i) {
        if (i != dot && !std::isdigit(static_cast<unsigned char>(target[i]))) return -1;
    }
    return std::stoi(std::string(target.substr(0, dot))) * 10 + (target[dot + 1] - '0');
}

std::string passMacro(std::string_view lightMode) {
    static const char* const kKnown[] = {"FORWARDBASE",  "FORWARDADD",   "DEFERRED",
                                         "SHADOWCASTER", "PREPASSBASE",  "PREPASSFINAL",
                                         "META",         "MOTIONVECTORS"};
    std::string name = toAsciiUpper(lightMode);
    for (const char* known : kKnown) {
        if (name == known) return "UNITY_PASS_" + name;
    }
    return "";
}

// The GLSL extension macros glslang's preprocessor predefines for HLSL programs too (measured
// with glslang 12.0: `#ifdef` on each). The DirectX compilers define none of them, and code
// written for both languages (FXAA 3.11 tests GL_ARB_gpu_shader5) takes its GLSL paths when it
// sees one.
constexpr const char* kGlslangPredefinedExtensions[] = {"GL_ARB_gpu_shader5",
                                                        "GL_FRAGMENT_PRECISION_HIGH",
                                                        "GL_core_profile",
                                                        "GL_ARB_texture_rectangle",
                                                        "GL_ARB_shading_language_420pack",
                                                        "GL_ARB_texture_gather",
                                                        "GL_ARB_shader_texture_lod",
                                                        "GL_ARB_derivative_control",
                                                        "GL_ARB_separate_shader_objects",
                                                        "GL_ARB_gpu_shader_fp64",
                                                        "GL_ARB_shader_image_load_store",
                                                        "GL_ARB_compute_shader",
                                                        "GL_ARB_sparse_texture2",
                                                        "GL_AMD_gpu_shader_half_float",
                                                        "GL_GOOGLE_include_directive",
                                                        "GL_EXT_shader_16bit_storage",
                                                        "GL_KHR_shader_subgroup_basic",
                                                        "GL_EXT_nonuniform_qualifier",
                                                        "GL_ARB_shader_draw_parameters",
                                                        "GL_ARB_viewport_array",
                                                        "GL_ARB_shader_bit_encoding"};

std::vector<PredefinedMacro> predefinedMacros(const DefineContext& context) {
    std::vector<PredefinedMacro> macros;
    auto define = [&macros](std::string name, std::string value) {
        macros.push_back({PredefinedMacro::Kind::Define, std::move(name), std::move(value)});
    };
    define("SHADER_API_VULKAN", "1");
    define("SHADER_API_DESKTOP", "1");
    int target = shaderTargetNumber(context.target);
    define("SHADER_TARGET", std::to_string(target < 0 ? 25 : target));
    define("UNITY_VERSION", std::to_string(kUnityVersion));
    if (std::string pass = passMacro(context.lightMode); !pass.empty()) define(pass, "1");
    if (const char* stage = stageMacro(context.stage)) define(stage, "1");
    if (context.language == shaderlab::ProgramLanguage::Glsl) {
        if (const char* stage = glslStageMacro(context.stage)) define(stage, "1");
    }
    if (context.language != shaderlab::ProgramLanguage::Glsl) {
        // glslang parses this HLSL intrinsic and then crashes generating SPIR-V for it; varc's
        // runtime renders with one sample per pixel (docs/SHADER_ABI.md).
        define("GetRenderTargetSampleCount()", "(1u)");
        for (const char* name : kGlslangPredefinedExtensions) {
            macros.push_back({PredefinedMacro::Kind::Undef, name, ""});
        }
    }
    if (context.language != shaderlab::ProgramLanguage::Glsl) {
        for (PredefinedMacro& macro : instancingOptionMacros(context.instancingOptions))
            macros.push_back(std::move(macro));
    }
    for (const std::string& keyword : context.keywords) define(keyword, "1");
    return macros;
}

std::string makePreamble(const DefineContext& context) {
    return writePreamble(predefinedMacros(context));
}

}  // namespace varc::driver
