// SPDX-License-Identifier: Apache-2.0
// generateSurfaceCode: the code of each generated pass follows the program's options and facts.
#include <gtest/gtest.h>

#include "varc/frontend/SurfaceCodeGenerator.h"

namespace varc::frontend {
namespace {

bool has(const std::string& text, std::string_view part) {
    return text.find(part) != std::string::npos;
}

shaderlab::SurfaceProgram lambert() {
    shaderlab::SurfaceProgram program;
    program.function = "surf";
    program.lightingModel = "Lambert";
    program.pragma = {1, 4, 5};
    return program;
}

SurfaceFacts lambertFacts() {
    SurfaceFacts facts;
    facts.inputMembers = {"uv_MainTex", "uv2_Detail", "viewDir", "color"};
    facts.outputType = "SurfaceOutput";
    facts.outputMembers = {"Albedo", "Normal", "Emission", "Specular", "Gloss", "Alpha"};
    facts.vertexInputMembers = {"vertex", "normal", "texcoord", "texcoord1", "color"};
    facts.programText = "sampler2D _MainTex; float4 _MainTex_ST; sampler2D _Detail;";
    return facts;
}

TEST(SurfaceCodeGenerator, ForwardBaseHasItsKeywordsAmbientVertexLightsAndEmission) {
    shaderlab::GeneratedCode code =
        generateSurfaceCode(lambert(), lambertFacts(), SurfacePassKind::ForwardBase);
    EXPECT_EQ(code.location, (SourceLocation{1, 4, 5}));
    EXPECT_TRUE(has(code.before, "#define UNITY_PASS_FORWARDBASE\n"));
    EXPECT_TRUE(has(code.before, "#pragma multi_compile_fwdbase\n#pragma multi_compile_fog\n"));
    EXPECT_TRUE(has(code.before, "#define INTERNAL_DATA\n"));  // o.Normal not written
    EXPECT_TRUE(has(code.after, "Shade4PointLights("));
    EXPECT_TRUE(has(code.after, "giInput.ambient = i.vertexLights;"));
    EXPECT_FALSE(has(code.after, "LightingLambert_GI"));  // the facts: no _GI function
    EXPECT_TRUE(has(code.after, "gi = UnityGlobalIllumination(giInput, 1.0, o.Normal);"));
    EXPECT_TRUE(has(code.after, "c += LightingLambert(o, gi);"));
    EXPECT_TRUE(has(code.after, "c.rgb += o.Emission;"));
    EXPECT_TRUE(has(code.after, "c.a = 1;"));
    // uv_/uv2_ members: TRANSFORM_TEX with NAME_ST, declared only where the program has none.
    EXPECT_TRUE(has(code.after, "surfIN.uv_MainTex = TRANSFORM_TEX(i.texcoord0, _MainTex);"))
        << code.after;
    EXPECT_TRUE(has(code.after, "surfIN.uv2_Detail = TRANSFORM_TEX(i.texcoord1, _Detail);"));
    EXPECT_TRUE(has(code.after, "float4 _Detail_ST;"));
    EXPECT_FALSE(has(code.after, "float4 _MainTex_ST;"));
    EXPECT_TRUE(has(code.after, "surfIN.viewDir = worldViewDir;"));
    EXPECT_TRUE(has(code.after, "surfIN.color = i.vertexColor;"));
}

TEST(SurfaceCodeGenerator, ForwardAddHasNoAmbientNoEmissionAndItsShadowsOption) {
    shaderlab::SurfaceProgram program = lambert();
    program.options.fullForwardShadows = true;
    program.options.noFog = true;
    program.options.noShadow = true;
    program.options.shortcutOptions = {"noshadow", "nolightmap"};
    shaderlab::GeneratedCode code =
        generateSurfaceCode(program, lambertFacts(), SurfacePassKind::ForwardAdd);
    EXPECT_TRUE(has(code.before, "#pragma multi_compile_fwdadd_fullshadows noshadow\n"));
    shaderlab::GeneratedCode base =
        generateSurfaceCode(program, lambertFacts(), SurfacePassKind::ForwardBase);
    EXPECT_TRUE(has(base.before, "#pragma multi_compile_fwdbase noshadow nolightmap\n"));
    EXPECT_FALSE(has(code.before, "multi_compile_fog"));
    EXPECT_FALSE(has(code.after, "Shade4PointLights"));
    EXPECT_FALSE(has(code.after, "o.Emission"));
    EXPECT_TRUE(has(code.after, "gi.light.color *= atten;"));
}

TEST(SurfaceCodeGenerator, TangentSpaceNormalsLegacyLightingFinalColorAndAlphaTest) {
    shaderlab::SurfaceProgram program = lambert();
    program.lightingModel = "Toon";
    program.options.finalColorFunction = "tint";
    program.options.alphaTestProperty = "_Cutoff";
    program.options.keepAlpha = true;
    SurfaceFacts facts = lambertFacts();
    facts.writesNormal = true;
    facts.inputHasInternalData = true;
    facts.lighting = LightingShape::LegacyViewDir;
    shaderlab::GeneratedCode code =
        generateSurfaceCode(program, facts, SurfacePassKind::ForwardBase);
    EXPECT_TRUE(has(code.before, "#define INTERNAL_DATA float3 internalSurfaceTtoW0;"));
    EXPECT_TRUE(has(code.after, "o.Normal = float3(0, 0, 1);"));
    EXPECT_TRUE(
        has(code.after,
            "float3 tangentSpace1 = float3(worldTangent.y, worldBinormal.y, worldNormal.y);"));
    EXPECT_TRUE(has(code.after, "surfIN.viewDir = tangentSpace0 * worldViewDir.x"));
    EXPECT_TRUE(has(code.after, "surfIN.internalSurfaceTtoW0 = tangentSpace0;"));
    EXPECT_TRUE(has(code.after, "clip(o.Alpha - _Cutoff);"));
    EXPECT_TRUE(has(code.after, "fixed _Cutoff;"));  // not named by the program
    EXPECT_TRUE(has(code.after, "c += LightingToon(o, lightDir, worldViewDir, atten);"));
    EXPECT_TRUE(has(code.after, "c.rgb += o.Albedo * ambient;"));
    EXPECT_TRUE(has(code.after, "tint(surfIN, o, c);"));
    EXPECT_FALSE(has(code.after, "c.a = 1;"));  // keepalpha
}

TEST(SurfaceCodeGenerator, ShadowCasterAppliesTheVertexModifierAndClips) {
    shaderlab::SurfaceProgram program = lambert();
    program.options.vertexFunction = "wave";
    program.options.alphaTestProperty = "_Cutoff";
    SurfaceFacts facts = lambertFacts();
    facts.vertexWritesInput = true;
    shaderlab::GeneratedCode code =
        generateSurfaceCode(program, facts, SurfacePassKind::ShadowCaster);
    EXPECT_TRUE(has(code.before, "#define UNITY_PASS_SHADOWCASTER\n"));
    EXPECT_TRUE(has(code.before, "#pragma multi_compile_shadowcaster\n"));
    EXPECT_TRUE(has(code.after, "wave(v, customInput);"));
    EXPECT_TRUE(has(code.after, "TRANSFER_SHADOW_CASTER_NORMALOFFSET(o)"));
    EXPECT_TRUE(has(code.after, "clip(o.Alpha - _Cutoff);"));
    EXPECT_TRUE(has(code.after, "SHADOW_CASTER_FRAGMENT(i)"));
    EXPECT_FALSE(has(code.after, "Lighting"));
}

// Without alphatest or clip() in the surface function the caster writes depth only: nothing but
// the position is interpolated (an unread interpolator is a Vulkan interface warning).
TEST(SurfaceCodeGenerator, ShadowCasterWithoutClippingInterpolatesOnlyThePosition) {
    shaderlab::SurfaceProgram program = lambert();
    program.options.vertexFunction = "wave";
    SurfaceFacts facts = lambertFacts();
    facts.vertexWritesInput = true;
    shaderlab::GeneratedCode code =
        generateSurfaceCode(program, facts, SurfacePassKind::ShadowCaster);
    EXPECT_TRUE(has(code.after, "wave(v, customInput);"));
    EXPECT_FALSE(has(code.after, "Input custom;"));
    EXPECT_FALSE(has(code.after, "worldPos : TEXCOORD"));
    EXPECT_FALSE(has(code.after, "surf(surfIN, o);"));
    facts.surfaceDiscards = true;
    code = generateSurfaceCode(program, facts, SurfacePassKind::ShadowCaster);
    EXPECT_TRUE(has(code.after, "surf(surfIN, o);"));
    EXPECT_TRUE(has(code.after, "Input custom;"));
}

// The base pass interpolates the vertex lights only where the fragment reads them.
TEST(SurfaceCodeGenerator, BaseInterpolatorsAreSwitchedByWhatTheFragmentReads) {
    shaderlab::GeneratedCode gi =
        generateSurfaceCode(lambert(), lambertFacts(), SurfacePassKind::ForwardBase);
    EXPECT_TRUE(has(gi.after, "#if UNITY_SHOULD_SAMPLE_SH\n#define VARC_SURF_AMBIENT 1\n"));
    EXPECT_TRUE(has(gi.after, "#define VARC_SURF_LIGHTMAP_UV 1"));
    SurfaceFacts legacy = lambertFacts();
    legacy.lighting = LightingShape::Legacy;
    shaderlab::GeneratedCode old =
        generateSurfaceCode(lambert(), legacy, SurfacePassKind::ForwardBase);
    EXPECT_TRUE(has(old.after, "#if 1\n#define VARC_SURF_AMBIENT 1\n"));
    EXPECT_FALSE(has(old.after, "#define VARC_SURF_LIGHTMAP_UV 1"));
    shaderlab::SurfaceProgram noAmbient = lambert();
    noAmbient.options.noAmbient = true;
    shaderlab::GeneratedCode none =
        generateSurfaceCode(noAmbient, lambertFacts(), SurfacePassKind::ForwardBase);
    EXPECT_FALSE(has(none.after, "#define VARC_SURF_AMBIENT"));
}

TEST(SurfaceCodeGenerator, PlainAlphaIsPremultipliedForStandardAndFadeOtherwise) {
    shaderlab::SurfaceProgram program = lambert();
    program.options.alpha = shaderlab::SurfaceOptions::Alpha::Blend;
    EXPECT_EQ(effectiveAlpha(program), shaderlab::SurfaceOptions::Alpha::Fade);
    program.lightingModel = "Standard";
    EXPECT_EQ(effectiveAlpha(program), shaderlab::SurfaceOptions::Alpha::Premultiply);
}

}  // namespace
}  // namespace varc::frontend
