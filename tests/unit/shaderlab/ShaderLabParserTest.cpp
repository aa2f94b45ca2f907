// SPDX-License-Identifier: Apache-2.0
// parseShaderLab: shader structure (SubShaders, Passes, Category, Fallback, ...) and locations.
#include <gtest/gtest.h>

#include "ShaderLabTestSupport.h"
#include "varc/shaderlab/ShaderLabParser.h"

namespace varc::shaderlab {
namespace {

using testing::parse;
using testing::trimMargin;

TEST(ShaderLabParser, ParsesShaderNameAndKeywordLocation) {
    auto outcome = parse("\n  Shader \"Custom/A B\" { }");
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    EXPECT_EQ(outcome.shader->name, "Custom/A B");
    EXPECT_EQ(outcome.shader->location, (SourceLocation{testing::kTestFile, 2, 3}));
    EXPECT_TRUE(outcome.shader->subShaders.empty());
    EXPECT_FALSE(outcome.diagnostics.hasErrors());
}

TEST(ShaderLabParser, ParsesSubShadersPassesNamesTagsAndLod) {
    auto outcome = parse(trimMargin(R"(
        |Shader "A" {
        |    SubShader {
        |        Tags { "Queue" = "Geometry" "RenderType" = "Opaque" }
        |        LOD 200
        |        Pass { Name "BASE" Tags { "LightMode" = "ForwardBase" } }
        |        Pass { Tags { "LightMode" = "ForwardAdd" } }
        |    }
        |    SubShader { Pass { } }
        |}
    )"));
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    const ShaderFile& shader = *outcome.shader;
    ASSERT_EQ(shader.subShaders.size(), 2u);
    const SubShader& first = shader.subShaders[0];
    EXPECT_EQ(first.location, (SourceLocation{testing::kTestFile, 2, 5}));
    EXPECT_EQ(first.lod, 200);
    EXPECT_EQ(first.tags, (Tags{{"Queue", "Geometry"}, {"RenderType", "Opaque"}}));
    ASSERT_EQ(first.passes.size(), 2u);
    EXPECT_EQ(first.passes[0].name, "BASE");
    EXPECT_EQ(first.passes[0].lightMode(), "ForwardBase");
    EXPECT_EQ(first.passes[0].location, (SourceLocation{testing::kTestFile, 5, 9}));
    EXPECT_EQ(first.passes[1].name, "");
    EXPECT_EQ(first.passes[1].lightMode(), "ForwardAdd");
    EXPECT_EQ(shader.subShaders[1].passes.size(), 1u);
}

TEST(ShaderLabParser, MatchesKeywordsIgnoringCase) {
    auto outcome = parse(R"(shader "A" { subshader { PASS { tags { "lightmode" = "Always" }
                            zwrite off cgprogram x endcg } } fallBack OFF })");
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    const Pass& pass = outcome.shader->subShaders.at(0).passes.at(0);
    EXPECT_EQ(pass.lightMode(), "Always");
    EXPECT_EQ(pass.state.zWrite.literal, "off");
    ASSERT_TRUE(pass.program);
    EXPECT_EQ(pass.program->text, " x ");
    EXPECT_TRUE(outcome.shader->fallbackOff);
}

TEST(ShaderLabParser, SkipsLineAndBlockCommentsBetweenTokens) {
    auto outcome = parse(trimMargin(R"(
        |// leading comment with "quotes" and { braces
        |Shader /* inline */ "A" /* multi
        |   line } */ {
        |    SubShader { // trailing
        |        Pass { Cull /* between */ Off }
        |    }
        |}
        |// after the end
    )"));
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    EXPECT_EQ(outcome.shader->subShaders.at(0).passes.at(0).state.cull.literal, "Off");
}

TEST(ShaderLabParser, ParsesUsePassWithKeywordLocationAndNoBody) {
    auto outcome = parse("Shader \"A\" { SubShader { Pass { } UsePass \"Other/SHADOWCASTER\" } }");
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    const auto& passes = outcome.shader->subShaders.at(0).passes;
    ASSERT_EQ(passes.size(), 2u);
    EXPECT_EQ(passes[1].usePass, "Other/SHADOWCASTER");
    EXPECT_EQ(passes[1].location, (SourceLocation{testing::kTestFile, 1, 35}));
    EXPECT_FALSE(passes[1].program);
    EXPECT_TRUE(passes[0].usePass.empty());
}

TEST(ShaderLabParser, SkipsGrabPassWithOrWithoutTextureName) {
    auto outcome = parse(R"(Shader "A" { SubShader {
        GrabPass { }
        GrabPass { "_BackgroundTexture" }
        GrabPass { Name "BASE" Tags { "LightMode" = "Always" } }
        Pass { Name "P" } } })");
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    const auto& passes = outcome.shader->subShaders.at(0).passes;
    ASSERT_EQ(passes.size(), 1u);
    EXPECT_EQ(passes[0].name, "P");
}

TEST(ShaderLabParser, ParsesFallbackNameCustomEditorAndDependency) {
    auto outcome = parse(trimMargin(R"(
        |Shader "A" {
        |    SubShader { Pass { } }
        |    Fallback "VertexLit"
        |    CustomEditor "MyEditor"
        |    Dependency "BaseMapShader" = "Hidden/Base"
        |}
    )"));
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    EXPECT_EQ(outcome.shader->fallback, "VertexLit");
    EXPECT_FALSE(outcome.shader->fallbackOff);
    EXPECT_EQ(outcome.shader->customEditor, "MyEditor");
    ASSERT_EQ(outcome.shader->dependencies.size(), 1u);
    EXPECT_EQ(outcome.shader->dependencies[0].first, "BaseMapShader");
    EXPECT_EQ(outcome.shader->dependencies[0].second, "Hidden/Base");
}

TEST(ShaderLabParser, RecordsExplicitFallbackOffWithoutName) {
    auto outcome = parse("Shader \"A\" { Fallback Off }");
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    EXPECT_FALSE(outcome.shader->fallback.has_value());
    EXPECT_TRUE(outcome.shader->fallbackOff);
}

TEST(ShaderLabParser, CategoryStateTagsAndLodReachEnclosedSubShadersAndPasses) {
    auto outcome = parse(trimMargin(R"(
        |Shader "A" {
        |    Category {
        |        Tags { "Queue" = "Transparent" "RenderType" = "Transparent" }
        |        LOD 300
        |        Blend SrcAlpha OneMinusSrcAlpha
        |        Cull Off
        |        SubShader {
        |            Tags { "RenderType" = "Fade" }
        |            Pass { Cull Back }
        |            Pass { }
        |        }
        |        ZWrite Off
        |    }
        |    SubShader { Pass { } }
        |}
    )"));
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    const SubShader& inCategory = outcome.shader->subShaders.at(0);
    EXPECT_EQ(inCategory.lod, 300);
    EXPECT_EQ(inCategory.tags, (Tags{{"RenderType", "Fade"}, {"Queue", "Transparent"}}));
    const RenderState& first = inCategory.passes.at(0).state;
    EXPECT_EQ(first.cull.literal, "Back");
    ASSERT_TRUE(first.blend);
    EXPECT_EQ(first.blend->src.literal, "SrcAlpha");
    EXPECT_EQ(first.zWrite.literal, "Off");  // written after the SubShader, still applies
    EXPECT_EQ(inCategory.passes.at(1).state.cull.literal, "Off");
    const SubShader& outside = outcome.shader->subShaders.at(1);
    EXPECT_EQ(outside.lod, 0);
    EXPECT_EQ(outside.passes.at(0).state, RenderState{});
}

// Unity accepts a negative LOD (it takes the first SubShader at or below maximumLOD).
TEST(ShaderLabParser, AcceptsANegativeLod) {
    auto outcome = parse("Shader \"A\" { SubShader { LOD -10 Pass { } } }");
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    EXPECT_EQ(outcome.shader->subShaders.at(0).lod, -10);
}

TEST(ShaderLabParser, SubShaderStateAppliesToEveryPassUnlessThePassOverrides) {
    auto outcome = parse(R"(Shader "A" { SubShader {
        ZTest Greater Cull Front
        Pass { Cull Back }
        Pass { }
        ZWrite Off } })");
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    const auto& passes = outcome.shader->subShaders.at(0).passes;
    EXPECT_EQ(passes.at(0).state.cull.literal, "Back");
    EXPECT_EQ(passes.at(0).state.zTest.literal, "Greater");
    EXPECT_EQ(passes.at(1).state.cull.literal, "Front");
    EXPECT_EQ(passes.at(1).state.zWrite.literal, "Off");
}

TEST(ShaderLabParser, SubShaderLightModeAppliesToPassesThatSetNone) {
    auto outcome = parse(trimMargin(R"(
        |Shader "A" {
        |    SubShader {
        |        Pass { Tags { "Queue" = "Geometry" } }
        |        Pass { Tags { "LightMode" = "ForwardAdd" } }
        |        UsePass "Other/SHADOWCASTER"
        |        Tags { "RenderType" = "Opaque" "lightmode" = "ForwardBase" }
        |    }
        |    SubShader { Tags { "RenderType" = "Opaque" } Pass { } }
        |}
    )"));
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    const auto& passes = outcome.shader->subShaders.at(0).passes;
    ASSERT_EQ(passes.size(), 3u);
    // Written after the passes, the SubShader's tag still applies; only LightMode is copied.
    EXPECT_EQ(passes[0].tags, (Tags{{"Queue", "Geometry"}, {"LightMode", "ForwardBase"}}));
    EXPECT_EQ(passes[0].lightMode(), "ForwardBase");
    EXPECT_EQ(passes[1].tags, (Tags{{"LightMode", "ForwardAdd"}}));  // the pass's own wins
    EXPECT_TRUE(passes[2].tags.empty());  // a UsePass keeps the named pass's tags
    EXPECT_TRUE(outcome.shader->subShaders.at(1).passes.at(0).tags.empty());
}

TEST(ShaderLabParser, CategoryLightModeReachesPassesThroughTheSubShader) {
    auto outcome = parse(trimMargin(R"(
        |Shader "A" {
        |    Category {
        |        SubShader { Pass { } }
        |        SubShader { Tags { "LightMode" = "Always" } Pass { } }
        |        Tags { "LightMode" = "ShadowCaster" }
        |    }
        |}
    )"));
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    EXPECT_EQ(outcome.shader->subShaders.at(0).passes.at(0).lightMode(), "ShadowCaster");
    EXPECT_EQ(outcome.shader->subShaders.at(1).passes.at(0).lightMode(), "Always");
}

TEST(ShaderLabParser, LaterTagWithSameKeyReplacesEarlierValue) {
    auto outcome = testing::parsePassBody(
        R"(Tags { "LightMode" = "ForwardBase" "Other" = "x" "lightmode" = "ForwardAdd" })");
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    EXPECT_EQ(outcome.shader->subShaders.at(0).passes.at(0).tags,
              (Tags{{"LightMode", "ForwardAdd"}, {"Other", "x"}}));
}

}  // namespace
}  // namespace varc::shaderlab
