// SPDX-License-Identifier: Apache-2.0
// fromShaderLab: ShaderLab render state literals and property references to pack render state.
#include <gtest/gtest.h>

#include "varc/driver/RenderStateConversion.h"

namespace varc {
namespace {

using driver::fromShaderLab;
using shaderlab::StateValue;

StateValue lit(const char* text) { return {text, ""}; }
StateValue prop(const char* name) { return {"", name}; }

TEST(RenderStateConversion, UnsetStateGivesUnityDefaults) {
    driver::ConvertedRenderState converted = fromShaderLab({});
    EXPECT_TRUE(converted.ok());
    EXPECT_EQ(converted.state, pack::PackRenderState{});
    EXPECT_FALSE(converted.state.blendEnabled);
    EXPECT_TRUE(converted.state.zWrite.value);
    EXPECT_EQ(converted.state.zTest.value, pack::CompareFunction::LessEqual);
    EXPECT_EQ(converted.state.cull.value, pack::CullMode::Back);
    EXPECT_EQ(converted.state.colorMask.value, pack::kColorWriteAll);
}

TEST(RenderStateConversion, LiteralsAreCaseInsensitive) {
    shaderlab::RenderState state;
    state.blend = shaderlab::BlendState{
        false, lit("srcalpha"), lit("OneMinusSrcAlpha"), {}, {}, lit("revsub"), {}};
    state.zWrite = lit("off");
    state.zTest = lit("GEQUAL");
    state.cull = lit("front");
    state.colorMask = lit("rgb");
    driver::ConvertedRenderState converted = fromShaderLab(state);
    ASSERT_TRUE(converted.ok()) << converted.errors[0];
    const pack::PackRenderState& out = converted.state;
    EXPECT_TRUE(out.blendEnabled);
    EXPECT_EQ(out.srcColor.value, pack::BlendFactor::SrcAlpha);
    EXPECT_EQ(out.srcAlpha.value, pack::BlendFactor::SrcAlpha);  // alpha copies color
    EXPECT_EQ(out.dstAlpha.value, pack::BlendFactor::OneMinusSrcAlpha);
    EXPECT_EQ(out.colorOp.value, pack::BlendOp::ReverseSubtract);
    EXPECT_EQ(out.alphaOp.value, pack::BlendOp::ReverseSubtract);
    EXPECT_FALSE(out.zWrite.value);
    EXPECT_EQ(out.zTest.value, pack::CompareFunction::GreaterEqual);
    EXPECT_EQ(out.cull.value, pack::CullMode::Front);
    EXPECT_EQ(out.colorMask.value,
              pack::kColorWriteRed | pack::kColorWriteGreen | pack::kColorWriteBlue);
}

TEST(RenderStateConversion, PropertiesAreKeptBesideDefaults) {
    shaderlab::RenderState state;
    state.blend =
        shaderlab::BlendState{false, prop("_SrcBlend"), prop("_DstBlend"), {}, lit("One"), {}, {}};
    state.zWrite = prop("_ZWrite");
    state.cull = prop("_Cull");
    driver::ConvertedRenderState converted = fromShaderLab(state);
    ASSERT_TRUE(converted.ok());
    const pack::PackRenderState& out = converted.state;
    EXPECT_EQ(out.srcColor.property, "_SrcBlend");
    EXPECT_EQ(out.srcColor.value, pack::BlendFactor::One);  // Unity's default
    EXPECT_EQ(out.dstColor.property, "_DstBlend");
    EXPECT_EQ(out.srcAlpha.property, "_SrcBlend");
    EXPECT_FALSE(out.dstAlpha.isProperty());
    EXPECT_EQ(out.dstAlpha.value, pack::BlendFactor::One);
    EXPECT_EQ(out.zWrite.property, "_ZWrite");
    EXPECT_EQ(out.cull.property, "_Cull");
}

TEST(RenderStateConversion, BlendOffAndOffsetAndStencil) {
    shaderlab::RenderState state;
    state.blend = shaderlab::BlendState{true, {}, {}, {}, {}, {}, {}};
    state.offset = std::make_pair(lit("-1"), lit("-2.5"));
    shaderlab::StencilState stencil;
    stencil.ref = lit("2");
    stencil.readMask = lit("255");
    stencil.writeMask = prop("_StencilWriteMask");
    stencil.front.comp = lit("equal");
    stencil.front.pass = lit("IncrWrap");
    stencil.back.comp = lit("Always");
    stencil.back.zFail = lit("DecrSat");
    state.stencil = stencil;
    driver::ConvertedRenderState converted = fromShaderLab(state);
    ASSERT_TRUE(converted.ok()) << converted.errors[0];
    const pack::PackRenderState& out = converted.state;
    EXPECT_FALSE(out.blendEnabled);
    EXPECT_EQ(out.offsetFactor.value, -1.0f);
    EXPECT_EQ(out.offsetUnits.value, -2.5f);
    EXPECT_TRUE(out.stencilEnabled);
    EXPECT_EQ(out.stencilRef.value, 2);
    EXPECT_EQ(out.stencilWriteMask.property, "_StencilWriteMask");
    EXPECT_EQ(out.front.comp.value, pack::CompareFunction::Equal);
    EXPECT_EQ(out.front.pass.value, pack::StencilOp::IncrementWrap);
    EXPECT_EQ(out.back.zFail.value, pack::StencilOp::DecrementSaturate);
}

TEST(RenderStateConversion, ZTestOffDisablesTheTestAndColorMaskZero) {
    shaderlab::RenderState state;
    state.zTest = lit("Off");
    state.colorMask = lit("0");
    driver::ConvertedRenderState converted = fromShaderLab(state);
    EXPECT_EQ(converted.state.zTest.value, pack::CompareFunction::Disabled);
    EXPECT_EQ(converted.state.colorMask.value, 0);
}

TEST(RenderStateConversion, UnknownLiteralsAreReported) {
    shaderlab::RenderState state;
    state.zTest = lit("LEqaul");
    state.blend = shaderlab::BlendState{false, lit("Onee"), lit("Zero"), {}, {}, {}, {}};
    state.colorMask = lit("RGBX");
    shaderlab::StencilState stencil;
    stencil.ref = lit("256");
    state.stencil = stencil;
    driver::ConvertedRenderState converted = fromShaderLab(state);
    ASSERT_EQ(converted.errors.size(), 4u);
    EXPECT_NE(converted.errors[0].find("Blend: unknown blend factor 'Onee'"), std::string::npos);
    EXPECT_NE(converted.errors[1].find("ZTest: unknown comparison 'LEqaul' (expected Less"),
              std::string::npos)
        << converted.errors[1];
    EXPECT_NE(converted.errors[2].find("ColorMask"), std::string::npos);
    EXPECT_NE(converted.errors[3].find("Stencil Ref: expected an integer 0..255, got '256'"),
              std::string::npos);
    EXPECT_EQ(converted.state.zTest.value, pack::CompareFunction::LessEqual);  // default kept
}

}  // namespace
}  // namespace varc
