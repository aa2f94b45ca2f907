// SPDX-License-Identifier: Apache-2.0
// parseShaderLab on the seed fixture shaders, read in place from ../shared/fixtures.
#include <gtest/gtest.h>

#include <string>

#include "ShaderLabTestSupport.h"
#include "varc/shaderlab/ShaderLabParser.h"

namespace varc::shaderlab {
namespace {

const std::string kLightingShader =
    VARC_SHARED_DIR "/fixtures/seed000-multiple-lights/My First Lighting Shader.shader";
const std::string kDeferredShader =
    VARC_SHARED_DIR "/fixtures/seed002-deferred-lights/DeferredShading.shader";

// The program's first captured line must be the rest of the file's line at its origin.
void expectOriginMatchesFile(const std::string& file, const ProgramBlock& program) {
    std::string line = testing::lineOf(file, program.origin.line);
    ASSERT_GE(line.size() + 1, program.origin.column);
    EXPECT_EQ(testing::firstLine(program.text), line.substr(program.origin.column - 1));
    EXPECT_EQ(program.origin.file, testing::kTestFile);
}

TEST(ShaderLabFixtures, ParsesMultipleLightsShader) {
    std::string text = testing::readFile(kLightingShader);
    ASSERT_FALSE(text.empty()) << "cannot read " << kLightingShader;
    auto outcome = testing::parse(text);
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    const ShaderFile& shader = *outcome.shader;
    EXPECT_EQ(shader.name, "Custom/My First Lighting Shader");
    ASSERT_EQ(shader.properties.size(), 4u);
    EXPECT_EQ(shader.properties[2].name, "_Metallic");
    EXPECT_EQ(shader.properties[2].attributes, (std::vector<std::string>{"Gamma"}));
    EXPECT_EQ(shader.properties[1].type, PropertyType::Texture2D);
    ASSERT_EQ(shader.subShaders.size(), 1u);
    const auto& passes = shader.subShaders[0].passes;
    ASSERT_EQ(passes.size(), 2u);
    EXPECT_EQ(passes[0].lightMode(), "ForwardBase");
    EXPECT_EQ(passes[1].lightMode(), "ForwardAdd");
    EXPECT_FALSE(passes[0].state.blend);
    ASSERT_TRUE(passes[1].state.blend);
    EXPECT_EQ(passes[1].state.blend->src.literal, "One");
    EXPECT_EQ(passes[1].state.blend->dst.literal, "One");
    EXPECT_EQ(passes[1].state.zWrite.literal, "Off");
    ASSERT_TRUE(passes[0].program && passes[1].program);
    EXPECT_NE(passes[0].program->text.find("#pragma multi_compile _ VERTEXLIGHT_ON"),
              std::string::npos);
    EXPECT_NE(passes[1].program->text.find("#pragma multi_compile_fwdadd"), std::string::npos);
    expectOriginMatchesFile(text, *passes[0].program);
    expectOriginMatchesFile(text, *passes[1].program);
    EXPECT_EQ(testing::lineOf(text, passes[0].program->origin.line), "\t\t\tCGPROGRAM");
    EXPECT_EQ(testing::lineOf(text, passes[1].location.line), "\t\tPass {");
}

TEST(ShaderLabFixtures, ParsesDeferredShadingShader) {
    std::string text = testing::readFile(kDeferredShader);
    ASSERT_FALSE(text.empty()) << "cannot read " << kDeferredShader;
    auto outcome = testing::parse(text);
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    const auto& passes = outcome.shader->subShaders.at(0).passes;
    ASSERT_EQ(passes.size(), 2u);
    const RenderState& light = passes[0].state;
    ASSERT_TRUE(light.blend);
    EXPECT_EQ(light.blend->src, (StateValue{{}, "_SrcBlend"}));
    EXPECT_EQ(light.blend->dst, (StateValue{{}, "_DstBlend"}));
    EXPECT_EQ(light.zWrite.literal, "Off");
    const RenderState& decode = passes[1].state;
    EXPECT_EQ(decode.cull.literal, "Off");
    EXPECT_EQ(decode.zTest.literal, "Always");
    ASSERT_TRUE(decode.stencil);
    EXPECT_EQ(decode.stencil->ref, (StateValue{{}, "_StencilNonBackground"}));
    EXPECT_EQ(decode.stencil->readMask, (StateValue{{}, "_StencilNonBackground"}));
    EXPECT_EQ(decode.stencil->back.comp.literal, "Equal");
    EXPECT_EQ(decode.stencil->front.comp.literal, "Equal");
    EXPECT_FALSE(decode.stencil->writeMask.isSet());
    ASSERT_TRUE(passes[0].program && passes[1].program);
    EXPECT_NE(passes[0].program->text.find("#pragma multi_compile_lightpass"), std::string::npos);
    EXPECT_NE(passes[1].program->text.find("return -log2(tex2D(_LightBuffer, i.uv));"),
              std::string::npos);
    expectOriginMatchesFile(text, *passes[0].program);
    expectOriginMatchesFile(text, *passes[1].program);
}

}  // namespace
}  // namespace varc::shaderlab
