// SPDX-License-Identifier: Apache-2.0
// Tests of the reflection rule that decides whether a shader is lit, on synthetic reflection data.
#include <gtest/gtest.h>

#include <algorithm>

#include "varc/properties/LightInputs.h"

namespace varc::properties {
namespace {

// A program whose uniform block has |members| and whose resources are |textures|.
pack::ProgramReflection program(std::vector<std::string> members,
                                std::vector<std::string> textures = {}) {
    pack::ProgramReflection reflection;
    pack::UniformBlock block;
    block.name = "$Globals";
    for (std::string& name : members) block.members.push_back({std::move(name), 0, 16, "float4"});
    reflection.uniformBlocks.push_back(std::move(block));
    for (std::string& name : textures) {
        pack::ResourceBinding resource;
        resource.name = std::move(name);
        reflection.resources.push_back(std::move(resource));
    }
    return reflection;
}

PassReflection pass(std::string lightMode, std::vector<pack::ProgramReflection> programs) {
    PassReflection reflection{std::move(lightMode), {}};
    for (size_t i = 0; i < programs.size(); ++i)
        reflection.variants.push_back(
            {"variant " + std::to_string(i), {program({"unity_ObjectToWorld"}), programs[i]}});
    return reflection;
}

TEST(LightInputs, ProgramReadingLightColourIsLit) {
    const LightInputReport report =
        lightInputsOf({pass("ForwardBase", {program({"_Color", "_LightColor0"}, {"_MainTex"})})});
    EXPECT_TRUE(report.lit());
    EXPECT_EQ(report.read, (std::vector<std::string>{"_LightColor0"}));
    EXPECT_TRUE(report.findings.empty());
}

TEST(LightInputs, ProgramReadingOnlyMainTexIsNotLit) {
    const LightInputReport report =
        lightInputsOf({pass("ForwardBase", {program({"_Color"}, {"_MainTex"})})});
    EXPECT_FALSE(report.lit());
    EXPECT_TRUE(report.read.empty());
    EXPECT_TRUE(report.findings.empty());
    EXPECT_TRUE(decideLightModel(report, false).notLit);
    EXPECT_TRUE(decideLightModel(report, false).litFailures.empty());
}

TEST(LightInputs, TexturesAndTheirSamplersAreLightInputs) {
    for (const char* name : {"_LightTexture0", "_LightTextureB0", "_ShadowMapTexture",
                             "sampler_LightTexture0", "_CameraGBufferTexture2", "unity_SHAr",
                             "unity_4LightPosX0", "unity_WorldToLight", "_LightMatrix0"})
        EXPECT_TRUE(isLightInput(name)) << name;
    for (const char* name : {"_MainTex", "sampler_MainTex", "unity_ObjectToWorld", "_LightTex",
                             "unity_SpecCube0", "_CameraDepthTexture", "sampler"})
        EXPECT_FALSE(isLightInput(name)) << name;
    const LightInputReport report =
        lightInputsOf({pass("ForwardAdd", {program({}, {"_LightTexture0", "_MainTex"})})});
    EXPECT_EQ(report.read, (std::vector<std::string>{"_LightTexture0"}));
}

TEST(LightInputs, NamesAreSortedAndUnique) {
    const std::vector<std::string_view>& names = lightInputNames();
    EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
    EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end());
}

TEST(LightInputs, ForwardAddWithoutLightInputIsAFinding) {
    const LightInputReport report = lightInputsOf(
        {pass("ForwardBase", {program({"_WorldSpaceLightPos0"})}),
         pass("forwardadd", {program({"_LightColor0"}), program({"_Color"}, {"_MainTex"})})});
    EXPECT_TRUE(report.lit());
    ASSERT_EQ(report.findings.size(), 1u);
    EXPECT_NE(report.findings[0].find("variant 1 reads no light input"), std::string::npos)
        << report.findings[0];
    EXPECT_NE(report.findings[0].find("(1 of 2 variants)"), std::string::npos);
    // The finding fails `lit` whatever the images show.
    EXPECT_EQ(decideLightModel(report, true).litFailures, report.findings);
}

TEST(LightInputs, ForwardBaseWithoutLightInputIsNoFinding) {
    const LightInputReport report =
        lightInputsOf({pass("ForwardBase", {program({"_Color"})}),
                       pass("ForwardAdd", {program({"_LightColor0"})})});
    EXPECT_TRUE(report.lit());
    EXPECT_TRUE(report.findings.empty());
}

TEST(LightInputs, UnlitForwardAddPassIsAFindingOfANotLitShader) {
    const LightInputReport report = lightInputsOf(
        {pass("ForwardBase", {program({"_Color"})}), pass("ForwardAdd", {program({"_Color"})})});
    EXPECT_FALSE(report.lit());
    const LightModelDecision decision = decideLightModel(report, false);
    EXPECT_TRUE(decision.notLit);
    ASSERT_EQ(decision.litFailures.size(), 1u);
    EXPECT_NE(decision.litFailures[0].find("ForwardAdd variant"), std::string::npos);
}

TEST(LightInputs, ResponseWithoutLightInputFailsLit) {
    const LightInputReport report = lightInputsOf({pass("ForwardBase", {program({"_Color"})})});
    const LightModelDecision decision = decideLightModel(report, true);
    EXPECT_FALSE(decision.notLit);
    ASSERT_EQ(decision.litFailures.size(), 1u);
    EXPECT_NE(decision.litFailures[0].find("light response without a light input"),
              std::string::npos);
}

TEST(LightInputs, LitShaderIsNeverNotLit) {
    const LightInputReport report = lightInputsOf({pass("ForwardBase", {program({"unity_SHAr"})})});
    EXPECT_FALSE(decideLightModel(report, false).notLit);
    EXPECT_TRUE(decideLightModel(report, false).litFailures.empty());
    EXPECT_TRUE(decideLightModel(report, true).litFailures.empty());
}

}  // namespace
}  // namespace varc::properties
