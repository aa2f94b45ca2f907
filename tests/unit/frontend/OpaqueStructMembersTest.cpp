// SPDX-License-Identifier: Apache-2.0
// findOpaqueStructMember and combineStructTextureMembers: textures and samplers inside structs,
// and the structs that hold none.
#include <gtest/gtest.h>

#include "varc/frontend/OpaqueStructMembers.h"

namespace varc::frontend {
namespace {

TEST(OpaqueStructMembers, FindsATextureMember) {
    auto found = findOpaqueStructMember(
        "float4 _Color;\nstruct TexAndSampler {\n  float scale;\n  Texture2D tex;\n"
        "  SamplerState samp;\n};\n");
    ASSERT_TRUE(found);
    EXPECT_EQ(found->structName, "TexAndSampler");
    EXPECT_EQ(found->type, "Texture2D");
    EXPECT_EQ(found->member, "tex");
    EXPECT_EQ(found->file, 0u);
    EXPECT_EQ(found->line, 4u);
}

TEST(OpaqueStructMembers, FindsSamplerStatesAndTemplatedTextures) {
    auto state = findOpaqueStructMember("struct S { float2 uv; SamplerComparisonState s; };");
    ASSERT_TRUE(state);
    EXPECT_EQ(state->type, "SamplerComparisonState");
    EXPECT_EQ(state->member, "s");
    auto templated = findOpaqueStructMember("struct S { const Texture2DArray<float4> t; };");
    ASSERT_TRUE(templated);
    EXPECT_EQ(templated->type, "Texture2DArray");
    EXPECT_EQ(templated->member, "t");
}

// glslang compiles these inside a struct, so they are no reason to refuse one.
TEST(OpaqueStructMembers, CombinedSamplersAndStorageTexturesAreNotReported) {
    EXPECT_FALSE(findOpaqueStructMember("struct S { float2 uv; sampler2D map; };"));
    EXPECT_FALSE(findOpaqueStructMember("struct S { samplerCUBE_half cube; };"));
    EXPECT_FALSE(findOpaqueStructMember("struct S { RWTexture2D<float4> target; };"));
}

TEST(OpaqueStructMembers, MapsTheLineThroughLineDirectives) {
    auto found = findOpaqueStructMember("#line 20 3\nstruct S {\n  float a;\n  TextureCube c;\n};");
    ASSERT_TRUE(found);
    EXPECT_EQ(found->file, 3u);
    EXPECT_EQ(found->line, 22u);
}

TEST(OpaqueStructMembers, IgnoresPlainStructsAndGlobalTextures) {
    EXPECT_FALSE(findOpaqueStructMember(
        "Texture2D _MainTex; SamplerState sampler_MainTex; sampler2D _Other;\n"
        "struct v2f { float4 pos : SV_POSITION; float2 uv : TEXCOORD0; };\n"
        "float4 frag(v2f i) : SV_Target { return _MainTex.Sample(sampler_MainTex, i.uv); }"));
    // Names that only start like a sampler type, and a function using one, are not members.
    EXPECT_FALSE(findOpaqueStructMember("struct S { float TextureCount; int2 TextureSize; };"));
    EXPECT_FALSE(findOpaqueStructMember("struct S { TextureInfo info; };"));
    EXPECT_FALSE(
        findOpaqueStructMember("struct S { float a; };\n"
                               "float4 f(Texture2D t, float2 uv) { return 0; }"));
}

TEST(OpaqueStructMembers, TextureMembersBecomeCombinedSamplersKeepingColumns) {
    EXPECT_EQ(
        combineStructTextureMembers("struct S {\n  Texture2D<float4> t;\n  SamplerState s;\n};"),
        "struct S {\n  sampler2D         t;\n  SamplerState s;\n};");
    EXPECT_EQ(combineStructTextureMembers("struct A { TextureCube c; Texture3D v; Texture1D l; };"),
              "struct A { samplerCUBE c; sampler3D v; sampler1D l; };");
    // A comment keeps its place; a line break inside template arguments stays.
    EXPECT_EQ(combineStructTextureMembers("struct B { /*x*/ Texture2D<\nfloat4> t; };"),
              "struct B { /*x*/ sampler2D \n        t; };");
}

TEST(OpaqueStructMembers, LeavesWhatHasNoCombinedSampler) {
    const std::string text =
        "Texture2D _MainTex;\nstruct S { Texture2DArray a; SamplerState s; float4 c; };\n"
        "float4 f(Texture2D t) { return 0; }";
    EXPECT_EQ(combineStructTextureMembers(text), text);
}

}  // namespace
}  // namespace varc::frontend
