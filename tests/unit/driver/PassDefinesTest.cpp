// SPDX-License-Identifier: Apache-2.0
// The predefined macros: target numbers, pass macros from LightMode, stage and keyword defines.
#include <gtest/gtest.h>

#include "varc/driver/InstancingOptions.h"
#include "varc/driver/PassDefines.h"
#include "varc/variants/PassKeywords.h"

namespace varc::driver {
namespace {

TEST(PassDefines, ParsesShaderTargets) {
    EXPECT_EQ(shaderTargetNumber(""), 25);
    EXPECT_EQ(shaderTargetNumber("3.0"), 30);
    EXPECT_EQ(shaderTargetNumber("4.5"), 45);
    EXPECT_EQ(shaderTargetNumber("3"), -1);
    EXPECT_EQ(shaderTargetNumber("x.0"), -1);
}

TEST(PassDefines, MapsLightModeToPassMacroCaseInsensitively) {
    EXPECT_EQ(passMacro("ForwardBase"), "UNITY_PASS_FORWARDBASE");
    EXPECT_EQ(passMacro("FORWARDADD"), "UNITY_PASS_FORWARDADD");
    EXPECT_EQ(passMacro("Deferred"), "UNITY_PASS_DEFERRED");
    EXPECT_EQ(passMacro("ShadowCaster"), "UNITY_PASS_SHADOWCASTER");
    EXPECT_EQ(passMacro("Always"), "");
    EXPECT_EQ(passMacro(""), "");
}

TEST(PassDefines, PreambleListsApiTargetPassStageAndKeywordsInOrder) {
    DefineContext context{"ForwardAdd",
                          "3.0",
                          shaderlab::ProgramLanguage::Cg,
                          Stage::Fragment,
                          {"POINT", "SHADOWS_CUBE"},
                          {}};
    std::string preamble = makePreamble(context);
    std::string defines;
    for (size_t at = 0; at < preamble.size();) {
        size_t end = preamble.find('\n', at) + 1;
        if (preamble.compare(at, 7, "#define") == 0) defines += preamble.substr(at, end - at);
        at = end;
    }
    EXPECT_EQ(defines,
              "#define SHADER_API_VULKAN 1\n"
              "#define SHADER_API_DESKTOP 1\n"
              "#define SHADER_TARGET 30\n"
              "#define UNITY_VERSION 201940\n"
              "#define UNITY_PASS_FORWARDADD 1\n"
              "#define SHADER_STAGE_FRAGMENT 1\n"
              "#define GetRenderTargetSampleCount() (1u)\n"
              "#define POINT 1\n"
              "#define SHADOWS_CUBE 1\n");
    // HLSL sees none of the GLSL extension macros glslang predefines.
    EXPECT_NE(preamble.find("#undef GL_ARB_gpu_shader5\n"), std::string::npos);
}

TEST(PassDefines, GlslProgramsAlsoGetTheVertexOrFragmentSelector) {
    DefineContext context{"", "", shaderlab::ProgramLanguage::Glsl, Stage::Vertex, {}, {}};
    std::string preamble = makePreamble(context);
    EXPECT_NE(preamble.find("#define VERTEX 1\n"), std::string::npos);
    EXPECT_EQ(preamble.find("FRAGMENT"), std::string::npos);
    EXPECT_NE(preamble.find("#define SHADER_TARGET 25\n"), std::string::npos);
    EXPECT_EQ(preamble.find("GetRenderTargetSampleCount"), std::string::npos);
    EXPECT_EQ(preamble.find("#undef"), std::string::npos);
}

// `#pragma instancing_options` (Unity manual, "GPU instancing"): each documented switch becomes
// its macro, before the keywords; malformed values and unknown switches define nothing.
TEST(PassDefines, InstancingOptionsBecomeUnityMacros) {
    std::vector<PredefinedMacro> macros = instancingOptionMacros(
        {"procedural:setup", "maxcount:50", "forcemaxcount:8", "assumeuniformscaling", "nomatrices",
         "lodfade", "renderinglayer", "nolodfade", "nolightprobe", "nolightmap", "maxcount:x",
         "procedural:", "bogus"});
    std::string text = writePreamble(macros);
    EXPECT_EQ(text,
              "#define UNITY_INSTANCING_PROCEDURAL_FUNC setup\n"
              "#define UNITY_MAX_INSTANCE_COUNT 50\n"
              "#define UNITY_FORCE_MAX_INSTANCE_COUNT 8\n"
              "#define UNITY_ASSUME_UNIFORM_SCALING 1\n"
              "#define UNITY_DONT_INSTANCE_OBJECT_MATRICES 1\n"
              "#define UNITY_INSTANCED_LOD_FADE 1\n"
              "#define UNITY_INSTANCED_RENDERING_LAYER 1\n");
    // The last of two counts wins.
    EXPECT_EQ(writePreamble(instancingOptionMacros({"maxcount:10", "maxcount:20"})),
              "#define UNITY_MAX_INSTANCE_COUNT 20\n");

    DefineContext context{"",
                          "3.5",
                          shaderlab::ProgramLanguage::Cg,
                          Stage::Vertex,
                          {"INSTANCING_ON"},
                          {"maxcount:16"}};
    std::string preamble = makePreamble(context);
    size_t option = preamble.find("#define UNITY_MAX_INSTANCE_COUNT 16\n");
    ASSERT_NE(option, std::string::npos);
    EXPECT_LT(option, preamble.find("#define INSTANCING_ON 1\n"));
}

}  // namespace
}  // namespace varc::driver
