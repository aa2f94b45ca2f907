// SPDX-License-Identifier: Apache-2.0
// The predefined macros: target numbers, pass macros from LightMode, stage and keyword defines.
#include <gtest/gtest.h>

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
                          {"POINT", "SHADOWS_CUBE"}};
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
    DefineContext context{"", "", shaderlab::ProgramLanguage::Glsl, Stage::Vertex, {}};
    std::string preamble = makePreamble(context);
    EXPECT_NE(preamble.find("#define VERTEX 1\n"), std::string::npos);
    EXPECT_EQ(preamble.find("FRAGMENT"), std::string::npos);
    EXPECT_NE(preamble.find("#define SHADER_TARGET 25\n"), std::string::npos);
    EXPECT_EQ(preamble.find("GetRenderTargetSampleCount"), std::string::npos);
    EXPECT_EQ(preamble.find("#undef"), std::string::npos);
}

}  // namespace
}  // namespace varc::driver
