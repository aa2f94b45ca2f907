// SPDX-License-Identifier: Apache-2.0
// findCbufferRedeclaration: globals that redeclare a cbuffer member with another type (glslang
// crashes on them), and the declarations that are no such thing.
#include <gtest/gtest.h>

#include "varc/frontend/CbufferRedeclarations.h"

namespace varc::frontend {
namespace {

constexpr const char* kBuiltins = "cbuffer UnityLighting {\n half4 _LightColor0;\n};\n";

TEST(CbufferRedeclarations, FindsAGlobalOfAnotherShape) {
    auto found = findCbufferRedeclaration(std::string(kBuiltins) + "fixed3 _LightColor0;\n");
    ASSERT_TRUE(found);
    EXPECT_EQ(found->name, "_LightColor0");
    EXPECT_EQ(found->type, "fixed3");
    EXPECT_EQ(found->memberType, "half4");
    EXPECT_EQ(found->cbufferName, "UnityLighting");
    EXPECT_EQ(found->line, 4u);
    auto uniform = findCbufferRedeclaration("#line 10 2\n" + std::string(kBuiltins) +
                                            "uniform float _LightColor0 : register(c0);");
    ASSERT_TRUE(uniform);
    EXPECT_EQ(uniform->type, "float");
    EXPECT_EQ(uniform->file, 2u);
    EXPECT_EQ(uniform->line, 13u);
}

// glslang crashes the same way on two globals of one name (found by the build fuzz target).
TEST(CbufferRedeclarations, FindsTwoGlobalsOfOneNameAndDifferentTypes) {
    auto found = findCbufferRedeclaration("sampler2D _A;\nfloat4 _A;");
    ASSERT_TRUE(found);
    EXPECT_EQ(found->memberType, "sampler2D");
    EXPECT_EQ(found->type, "float4");
    EXPECT_EQ(found->cbufferName, "");
    EXPECT_EQ(found->line, 2u);
    EXPECT_FALSE(findCbufferRedeclaration("half3 _A;\nfloat3 _A;"));
}

// The second crash the build fuzz target found: an array of the name of a plain global, even one
// whose brackets never close.
TEST(CbufferRedeclarations, FindsAnArrayOfTheNameOfAPlainGlobal) {
    auto found = findCbufferRedeclaration("float4 _A;\nfloat4 _A[ST;");
    ASSERT_TRUE(found);
    EXPECT_EQ(found->memberType, "float4");
    EXPECT_EQ(found->type, "float4[]");
    EXPECT_EQ(found->line, 2u);
    auto member = findCbufferRedeclaration("cbuffer B {\n float4 _C[4];\n};\nfloat4 _C;");
    ASSERT_TRUE(member);
    EXPECT_EQ(member->memberType, "float4[]");
    EXPECT_FALSE(findCbufferRedeclaration("cbuffer B {\n float4 _C[4];\n};\nhalf4 _C[4];"));
}

TEST(CbufferRedeclarations, TheSameShapeInAnotherPrecisionIsNotReported) {
    EXPECT_FALSE(findCbufferRedeclaration(std::string(kBuiltins) + "fixed4 _LightColor0;"));
    EXPECT_FALSE(findCbufferRedeclaration(std::string(kBuiltins) + "float4 _LightColor0;"));
    EXPECT_FALSE(findCbufferRedeclaration(std::string(kBuiltins) + "min16float4 _LightColor0;"));
}

TEST(CbufferRedeclarations, ParametersLocalsAndMembersAreNotGlobals) {
    const std::string builtins = kBuiltins;
    EXPECT_FALSE(findCbufferRedeclaration(
        builtins + "float4 f(float3 _LightColor0 : TEXCOORD0) { float3 _LightColor0 = 0; }"));
    EXPECT_FALSE(findCbufferRedeclaration(builtins + "struct S { float3 _LightColor0; };"));
    EXPECT_FALSE(findCbufferRedeclaration(builtins + "float3 _Other;"));
    EXPECT_FALSE(findCbufferRedeclaration("fixed3 _LightColor0;"));
}

}  // namespace
}  // namespace varc::frontend
