// SPDX-License-Identifier: Apache-2.0
// parseShaderLab: render-state commands, stencil blocks and ignored legacy commands.
#include <gtest/gtest.h>

#include "ShaderLabTestSupport.h"
#include "varc/shaderlab/ShaderLabParser.h"

namespace varc::shaderlab {
namespace {

using testing::parsePassBody;

StateValue literal(std::string text) { return StateValue{std::move(text), {}}; }
StateValue property(std::string name) { return StateValue{{}, std::move(name)}; }

// The state of the only pass of `Shader "T" { SubShader { Pass { <body> } } }`; fails the
// test when parsing fails.
RenderState passState(std::string_view body) {
    auto outcome = parsePassBody(body);
    EXPECT_TRUE(outcome.shader) << body << ": " << outcome.firstMessage();
    if (!outcome.shader) return {};
    return outcome.shader->subShaders.at(0).passes.at(0).state;
}

TEST(RenderStateParser, ParsesBlendOffAndColorFactors) {
    RenderState off = passState("Blend Off");
    ASSERT_TRUE(off.blend);
    EXPECT_TRUE(off.blend->off);
    RenderState additive = passState("Blend One One");
    ASSERT_TRUE(additive.blend);
    EXPECT_FALSE(additive.blend->off);
    EXPECT_EQ(additive.blend->src, literal("One"));
    EXPECT_EQ(additive.blend->dst, literal("One"));
    EXPECT_FALSE(additive.blend->srcAlpha.isSet());
}

TEST(RenderStateParser, ParsesSeparateAlphaBlendFactors) {
    RenderState state = passState("Blend SrcAlpha OneMinusSrcAlpha, One Zero");
    ASSERT_TRUE(state.blend);
    EXPECT_EQ(state.blend->src, literal("SrcAlpha"));
    EXPECT_EQ(state.blend->dst, literal("OneMinusSrcAlpha"));
    EXPECT_EQ(state.blend->srcAlpha, literal("One"));
    EXPECT_EQ(state.blend->dstAlpha, literal("Zero"));
}

TEST(RenderStateParser, ParsesBlendFactorsFromPropertyReferences) {
    RenderState state = passState("Blend [_SrcBlend] [_DstBlend], [_SrcA] One");
    ASSERT_TRUE(state.blend);
    EXPECT_EQ(state.blend->src, property("_SrcBlend"));
    EXPECT_TRUE(state.blend->src.isProperty());
    EXPECT_EQ(state.blend->dst, property("_DstBlend"));
    EXPECT_EQ(state.blend->srcAlpha, property("_SrcA"));
    EXPECT_EQ(state.blend->dstAlpha, literal("One"));
}

TEST(RenderStateParser, RecordsOnlyRenderTargetZeroBlend) {
    RenderState state = passState("Blend 0 DstColor Zero Blend 1 One One BlendOp 2 Max");
    ASSERT_TRUE(state.blend);
    EXPECT_EQ(state.blend->src, literal("DstColor"));
    EXPECT_EQ(state.blend->dst, literal("Zero"));
    EXPECT_FALSE(state.blend->op.isSet());
    RenderState otherOnly = passState("Blend 3 One One");
    EXPECT_FALSE(otherOnly.blend);
}

TEST(RenderStateParser, ParsesBlendOpWithOptionalAlphaOperation) {
    RenderState state = passState("BlendOp RevSub, Max Blend One One");
    ASSERT_TRUE(state.blend);
    EXPECT_EQ(state.blend->op, literal("RevSub"));
    EXPECT_EQ(state.blend->opAlpha, literal("Max"));
    EXPECT_EQ(state.blend->src, literal("One"));  // Blend after BlendOp keeps the op
    RenderState onlyOp = passState("BlendOp [_Op]");
    ASSERT_TRUE(onlyOp.blend);
    EXPECT_EQ(onlyOp.blend->op, property("_Op"));
    EXPECT_FALSE(onlyOp.blend->src.isSet());
}

TEST(RenderStateParser, ParsesDepthAndCullCommandsWithLiteralsOrProperties) {
    RenderState state = passState("ZWrite Off ZTest [_ZTest] Cull Front");
    EXPECT_EQ(state.zWrite, literal("Off"));
    EXPECT_EQ(state.zTest, property("_ZTest"));
    EXPECT_EQ(state.cull, literal("Front"));
    RenderState other = passState("ZWrite [_ZWrite] ZTest GEqual Cull [_Cull]");
    EXPECT_EQ(other.zWrite, property("_ZWrite"));
    EXPECT_EQ(other.zTest, literal("GEqual"));
    EXPECT_EQ(other.cull, property("_Cull"));
}

TEST(RenderStateParser, LaterCommandInTheSameScopeWins) {
    RenderState state = passState("Cull Back ZTest Less Cull Off Blend One One Blend Off");
    EXPECT_EQ(state.cull, literal("Off"));
    ASSERT_TRUE(state.blend);
    EXPECT_TRUE(state.blend->off);
}

TEST(RenderStateParser, ParsesColorMaskValuesAndTarget) {
    EXPECT_EQ(passState("ColorMask RGB").colorMask, literal("RGB"));
    EXPECT_EQ(passState("ColorMask 0").colorMask, literal("0"));
    EXPECT_EQ(passState("ColorMask A 0").colorMask, literal("A"));
    EXPECT_EQ(passState("ColorMask [_Mask]").colorMask, property("_Mask"));
    EXPECT_FALSE(passState("ColorMask RG 2").colorMask.isSet());
}

TEST(RenderStateParser, ParsesOffsetNumbersAndProperties) {
    RenderState state = passState("Offset -1, -1.5");
    ASSERT_TRUE(state.offset);
    EXPECT_EQ(state.offset->first, literal("-1"));
    EXPECT_EQ(state.offset->second, literal("-1.5"));
    RenderState props = passState("Offset [_Factor], [_Units]");
    ASSERT_TRUE(props.offset);
    EXPECT_EQ(props.offset->first, property("_Factor"));
    EXPECT_EQ(props.offset->second, property("_Units"));
}

TEST(RenderStateParser, ParsesAlphaToMaskConservativeAndZClip) {
    RenderState state = passState("AlphaToMask On Conservative True ZClip False");
    EXPECT_EQ(state.alphaToMask, literal("On"));
    // Unity reads AlphaToMask as a boolean.
    EXPECT_EQ(passState("AlphaToMask True").alphaToMask, literal("True"));
    EXPECT_EQ(state.conservative, literal("True"));
    EXPECT_EQ(state.zClip, literal("False"));
}

TEST(RenderStateParser, ParsesStencilWithBothFaceAndPerFaceEntries) {
    RenderState state = passState(R"(Stencil {
        Ref 2 ReadMask 255 WriteMask [_WriteMask]
        Comp Always Pass Replace Fail Keep ZFail DecrWrap
        CompBack Equal PassFront IncrSat FailBack Zero ZFailFront Invert })");
    ASSERT_TRUE(state.stencil);
    const StencilState& s = *state.stencil;
    EXPECT_EQ(s.ref, literal("2"));
    EXPECT_EQ(s.readMask, literal("255"));
    EXPECT_EQ(s.writeMask, property("_WriteMask"));
    EXPECT_EQ(s.front.comp, literal("Always"));
    EXPECT_EQ(s.back.comp, literal("Equal"));
    EXPECT_EQ(s.front.pass, literal("IncrSat"));
    EXPECT_EQ(s.back.pass, literal("Replace"));
    EXPECT_EQ(s.front.fail, literal("Keep"));
    EXPECT_EQ(s.back.fail, literal("Zero"));
    EXPECT_EQ(s.front.zFail, literal("Invert"));
    EXPECT_EQ(s.back.zFail, literal("DecrWrap"));
}

TEST(RenderStateParser, StencilPerFaceEntryLeavesTheOtherFaceUnset) {
    RenderState state = passState("Stencil { Ref [_Ref] CompFront NotEqual }");
    ASSERT_TRUE(state.stencil);
    EXPECT_EQ(state.stencil->ref, property("_Ref"));
    EXPECT_EQ(state.stencil->front.comp, literal("NotEqual"));
    EXPECT_FALSE(state.stencil->back.comp.isSet());
}

TEST(RenderStateParser, IgnoresLegacyFixedFunctionCommands) {
    RenderState state = passState(R"(
        Lighting Off SeparateSpecular On ColorMaterial AmbientAndDiffuse
        Material { Diffuse [_Color] Ambient (1,1,1,1) Shininess 0.7 }
        SetTexture [_MainTex] { constantColor [_Color] combine texture * primary DOUBLE, texture }
        Fog { Mode Off }
        AlphaTest Greater [_Cutoff] AlphaTest Off AlphaTest GEqual 0.5
        BindChannels { Bind "Vertex", vertex Bind "texcoord", texcoord }
        Cull Off)");
    EXPECT_EQ(state.cull, literal("Off"));
    EXPECT_FALSE(state.blend);
}

// Unity accepts `ZTest Off` (image effects: no depth test) and `ZTest On` (the default test).
TEST(RenderStateParser, ZTestOffAndOnAreTheSpellingsUnityAccepts) {
    EXPECT_EQ(passState("ZTest Off").zTest, literal("Disabled"));
    EXPECT_EQ(passState("ZTest on").zTest, literal("LEqual"));
}

TEST(RenderStateParser, ReportsInvalidValuesAtTheValue) {
    auto ztest = parsePassBody("ZTest Sometimes");
    EXPECT_FALSE(ztest.shader);
    EXPECT_EQ(ztest.firstMessage(),
              "invalid ZTest value 'Sometimes'; expected Less, Greater, LEqual, GEqual, Equal, "
              "NotEqual, Always, Never, Disabled, Off, On");
    EXPECT_EQ(ztest.firstLocation(), (SourceLocation{testing::kTestFile, 1, 39}));
    auto blend = parsePassBody("Blend One Two");
    EXPECT_FALSE(blend.shader);
    EXPECT_EQ(blend.firstMessage().rfind("invalid Blend value 'Two'; expected One, Zero", 0), 0u);
    auto mask = parsePassBody("ColorMask RGBX");
    EXPECT_FALSE(mask.shader);
    EXPECT_EQ(mask.firstMessage(),
              "invalid ColorMask value 'RGBX'; expected 0 or channels such as RGB, RGBA, A");
    auto mask256 = parsePassBody("Stencil { ReadMask 256 }");
    EXPECT_FALSE(mask256.shader);
    EXPECT_EQ(mask256.firstMessage(),
              "invalid Stencil ReadMask value '256'; expected an integer from 0 to 255");
    auto negative = parsePassBody("Stencil { Ref -1 }");
    EXPECT_FALSE(negative.shader);
    EXPECT_EQ(negative.firstMessage(),
              "invalid Stencil Ref value '-1'; expected a non-negative integer");
}

// Unity accepts `Stencil Ref` above 255; the 8-bit stencil buffer sees its low byte.
TEST(RenderStateParser, AStencilRefAbove255KeepsItsLowByteWithAWarning) {
    auto ref = parsePassBody("Stencil { Ref 300 }");
    ASSERT_TRUE(ref.shader);
    const RenderState& state = ref.shader->subShaders[0].passes[0].state;
    ASSERT_TRUE(state.stencil);
    EXPECT_EQ(state.stencil->ref, literal("44"));
    EXPECT_NE(ref.firstMessage().find("acts as 44"), std::string::npos) << ref.firstMessage();
}

// LOD belongs to a SubShader; Unity ignores one inside a Pass.
TEST(RenderStateParser, ALodInsideAPassIsIgnoredWithAWarning) {
    auto lod = parsePassBody("LOD 200 ZWrite Off");
    ASSERT_TRUE(lod.shader);
    EXPECT_EQ(lod.shader->subShaders[0].passes[0].state.zWrite, literal("Off"));
    EXPECT_NE(lod.firstMessage().find("LOD inside a Pass has no effect"), std::string::npos);
    EXPECT_FALSE(parsePassBody("LOD high").shader);
}

TEST(RenderStateParser, ReportsMissingValuesAndMalformedPropertyReferences) {
    auto cull = parsePassBody("Cull }");
    EXPECT_FALSE(cull.shader);
    EXPECT_EQ(cull.firstMessage(), "expected a value for Cull, found '}'");
    auto reference = parsePassBody("ZWrite [_Z");
    EXPECT_FALSE(reference.shader);
    EXPECT_EQ(reference.firstMessage(), "expected ']' after property name _Z, found '}'");
    auto offset = parsePassBody("Offset 1 1");
    EXPECT_FALSE(offset.shader);
    EXPECT_EQ(offset.firstMessage(), "expected ',' between Offset factor and units, found '1'");
}

TEST(RenderStateParser, ReportsUnknownStencilAndShaderLabCommands) {
    auto stencil = parsePassBody("Stencil { CompSide Equal }");
    EXPECT_FALSE(stencil.shader);
    EXPECT_EQ(stencil.firstMessage(), "unknown Stencil command 'CompSide'");
    auto command = parsePassBody("ZWrite Off Foo On");
    EXPECT_FALSE(command.shader);
    EXPECT_EQ(command.firstMessage(), "unknown ShaderLab command 'Foo'");
    EXPECT_EQ(command.firstLocation(), (SourceLocation{testing::kTestFile, 1, 44}));
}

TEST(RenderStateParser, RejectsRenderStateAtShaderLevel) {
    auto outcome = testing::parse("Shader \"A\" { Cull Off }");
    EXPECT_FALSE(outcome.shader);
    EXPECT_EQ(outcome.firstMessage(),
              "render state command 'Cull' must be inside a Category, SubShader or Pass");
}

}  // namespace
}  // namespace varc::shaderlab
