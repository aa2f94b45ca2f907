// SPDX-License-Identifier: Apache-2.0
// rewriteHlslForGlslang and the front-face rewrites: what each rewrites, and what it leaves alone.
#include <gtest/gtest.h>

#include <algorithm>

#include "varc/frontend/HlslRewrites.h"

namespace varc::frontend {
namespace {

size_t lineCount(const std::string& text) { return std::count(text.begin(), text.end(), '\n'); }

TEST(HlslRewrites, ASwitchConditionIsConvertedToInt) {
    std::string text =
        "float4 f(float x : TEXCOORD0) : SV_Target {\n"
        "    switch (x * 2) { case 1: return 1; default: return 0; }\n}\n";
    EXPECT_EQ(rewriteHlslForGlslang(text),
              "float4 f(float x : TEXCOORD0) : SV_Target {\n"
              "    switch ((int)(x * 2)) { case 1: return 1; default: return 0; }\n}\n");
}

TEST(HlslRewrites, ASwitchWithUnsignedCasesIsLeftAlone) {
    std::string text = "uint f(uint x) { switch (x) { case 1u: return 1u; } return 0u; }\n";
    EXPECT_EQ(rewriteHlslForGlslang(text), text);
}

TEST(HlslRewrites, AWrittenLooseUniformGetsAPerInvocationCopy) {
    std::string text =
        "#line 1 0\n"
        "uniform float _Speed;\n"
        "float4 _Color;\n"
        "float twice() { _Speed *= 2; return _Speed; }\n"
        "float4 f() : SV_Target { _Color.a = twice(); return _Color; }\n";
    EXPECT_EQ(rewriteHlslForGlslang(text),
              "#line 1 0\n"
              "uniform float _Speed; static float _Speed_varcCopy = _Speed;\n"
              "float4 _Color; static float4 _Color_varcCopy = _Color;\n"
              "float twice() { _Speed_varcCopy *= 2; return _Speed_varcCopy; }\n"
              "float4 f() : SV_Target { _Color_varcCopy.a = twice(); return _Color_varcCopy; }\n");
}

TEST(HlslRewrites, EveryFormOfWriteIsSeenAndReadsAreNot) {
    for (std::string write : {"_A = 1;", "_A += 1;", "_A <<= 1;", "_A++;", "--_A;", "_A.x = 1;",
                              "_A[0] = 1;", "_A.xy[0] |= 1;"}) {
        std::string text = "float4 _A;\nvoid f() { " + write + " }\n";
        EXPECT_NE(rewriteHlslForGlslang(text).find("_A_varcCopy"), std::string::npos) << write;
    }
    for (std::string read : {"float b = _A.x;", "bool b = _A == 1;", "bool b = _A <= 1;",
                             "float b = _A - -1;", "float b = _A << 1;", "s._A = 1;"}) {
        std::string text = "float4 _A;\nstruct S { float _A; };\nvoid f(S s) { " + read + " }\n";
        EXPECT_EQ(rewriteHlslForGlslang(text), text) << read;
    }
}

TEST(HlslRewrites, MembersStaticsConstantsArraysAndResourcesAreNotCopied) {
    std::string text =
        "struct V { float _A; };\n"
        "cbuffer C { float _B; };\n"
        "static float _C;\n"
        "const float _D = 1;\n"
        "float _E[4];\n"
        "sampler2D _F;\n"
        "void f(V v) { v._A = 1; _C = 2; _E[0] = 3; }\n";
    EXPECT_EQ(rewriteHlslForGlslang(text), text);
}

TEST(HlslRewrites, AWrittenCbufferMemberGetsACopyAfterTheBlock) {
    std::string text =
        "cbuffer UnityLighting {\n float4 _LightColor0;\n float4 _Other;\n};\n"
        "float4 f() : SV_Target { _LightColor0 *= 0.5; return _LightColor0; }\n";
    EXPECT_EQ(rewriteHlslForGlslang(text),
              "cbuffer UnityLighting {\n float4 _LightColor0;\n float4 _Other;\n}; static float4 "
              "_LightColor0_varcCopy = _LightColor0;\n"
              "float4 f() : SV_Target { _LightColor0_varcCopy *= 0.5; return "
              "_LightColor0_varcCopy; }\n");
}

TEST(HlslRewrites, SeveralDeclaratorsAndParametersOfTheSameNameStayConsistent) {
    std::string text = "float _A, _B;\nfloat g(float _A) { _A = 1; return _A + _B; }\n";
    EXPECT_EQ(rewriteHlslForGlslang(text),
              "float _A, _B; static float _A_varcCopy = _A;\n"
              "float g(float _A_varcCopy) { _A_varcCopy = 1; return _A_varcCopy + _B; }\n");
}

TEST(HlslRewrites, MatrixSwizzlesOfSeveralElementsAreSpelledOut) {
    std::string text =
        "float4x4 unity_MatrixV;\nfloat3 f() { return unity_MatrixV._m20_m21_m22 +"
        " unity_MatrixV._11_22_33 + unity_MatrixV._m03; }\n";
    EXPECT_EQ(rewriteHlslForGlslang(text),
              "float4x4 unity_MatrixV;\nfloat3 f() { return float3(unity_MatrixV[2][0], "
              "unity_MatrixV[2][1], unity_MatrixV[2][2]) + float3(unity_MatrixV[0][0], "
              "unity_MatrixV[1][1], unity_MatrixV[2][2]) + unity_MatrixV._m03; }\n");
    std::string notSwizzles = "float4 f(S s) { return s.m._m00_m11.xxxx + v._m44_m00 + v._xy; }\n";
    EXPECT_EQ(rewriteHlslForGlslang(notSwizzles), notSwizzles);
}

// Unity's procedural-instancing example inverts a scale-and-translate matrix in place: a simple
// assignment to a swizzle stays (glslang accepts it), a compound one becomes a simple one.
TEST(HlslRewrites, WrittenMatrixSwizzlesBecomeSimpleAssignments) {
    std::string text =
        "static float4x4 M;\nvoid f(float s) { M._14_24_34 *= -1; M._11_22_33 = 1.0f / "
        "M._11_22_33; M._m00_m11 += float2(s, (s + 1)); }\n";
    EXPECT_EQ(rewriteHlslForGlslang(text),
              "static float4x4 M;\nvoid f(float s) { M._14_24_34 = float3(M[0][3], M[1][3], "
              "M[2][3]) * ( -1); M._11_22_33 = 1.0f / float3(M[0][0], M[1][1], M[2][2]); "
              "M._m00_m11 = float2(M[0][0], M[1][1]) + ( float2(s, (s + 1))); }\n");
}

TEST(HlslRewrites, HexLiteralsWiderThan32BitsKeepTheirLow32Bits) {
    std::string text =
        "uint h(uint n) { return n * 0x1376312589U + 0x0000FFFFFFFF + 0x7fffffffu; }\n";
    EXPECT_EQ(rewriteHlslForGlslang(text),
              "uint h(uint n) { return n * 0x76312589U + 0x0000FFFFFFFF + 0x7fffffffu; }\n");
}

TEST(HlslRewrites, WideHexLiteralsAreCutBeforePreprocessingToo) {
    EXPECT_EQ(
        truncateWideHexLiterals("#define K 0x1376312589U\nuint a = K + x0x123456789 + 0xFFu;"),
        "#define K 0x76312589U\nuint a = K + x0x123456789 + 0xFFu;");
}

TEST(HlslRewrites, EmptyMemberDeclarationsAreDropped) {
    std::string text =
        "cbuffer C {\n float a;\n ;\n float b;; };\nstruct S { ; float c; };\n"
        "float g;\n ;\nfloat f() { ; return 0; }\n";
    EXPECT_EQ(rewriteHlslForGlslang(text),
              "cbuffer C {\n float a;\n  \n float b;  };\nstruct S {   float c; };\n"
              "float g;\n  \nfloat f() { ; return 0; }\n");
}

TEST(HlslRewrites, ALocalNamedInItsOwnInitializerIsDeclaredFirst) {
    std::string text =
        "V g(V o, float x);\nvoid f() {\n    V o = g(o, 1);\n    float4 c = c.x;\n}\n";
    EXPECT_EQ(rewriteHlslForGlslang(text),
              "V g(V o, float x);\nvoid f() {\n    V o; o = g(o, 1);\n    float4 c; c = c.x;\n}\n");
    for (std::string kept : {"float a = b.a;", "const float a = a;", "float a = 1, b = a;",
                             "float a = a, b = 1;", "for (float a = a; ;) {}", "float a == a;"}) {
        std::string other = "void f() { " + kept + " }\n";
        EXPECT_EQ(rewriteHlslForGlslang(other), other) << kept;
    }
}

TEST(HlslRewrites, ResourcesDeclaredInACbufferMoveBeforeIt) {
    std::string text =
        "cbuffer M {\n  sampler2D _A;\n  float4 _A_ST;\n  Texture2D<float4>\n _B;\n"
        "  uniform SamplerState sampler_B; };\ncbuffer N { float _C; };\n";
    EXPECT_EQ(rewriteHlslForGlslang(text),
              "sampler2D _A; Texture2D<float4>  _B; uniform SamplerState sampler_B; cbuffer M {\n"
              "               \n  float4 _A_ST;\n" +
                  std::string(19, ' ') + "\n" + std::string(4, ' ') + "\n" + std::string(34, ' ') +
                  "};\n"
                  "cbuffer N { float _C; };\n");
}

TEST(HlslRewrites, ArgumentsOfAnUnmatchedCallAreCastToTheParameterTypes) {
    std::string text =
        "float3x3 R(const float a, in float3 axis, out float s, S t) { s = a; }\n"
        "float3x3 f(float4 v, S t) { float s; return R(v.xy * 2, v, s, t); }\n";
    EXPECT_EQ(rewriteHlslForGlslang(text, {"R"}),
              "float3x3 R(const float a, in float3 axis, out float s, S t) { s = a; }\n"
              "float3x3 f(float4 v, S t) { float s; return R((float)(v.xy * 2), (float3)(v), s, "
              "t); }\n");
    EXPECT_EQ(rewriteHlslForGlslang(text), text);  // only the functions glslang named
    std::string overloaded =
        "float g(float a) { return a; }\nfloat g(float2 a) { return a.x; }\n"
        "float f(float4 v) { return g(v); }\n";
    EXPECT_EQ(rewriteHlslForGlslang(overloaded, {"g"}), overloaded);
}

TEST(HlslRewrites, FrontFaceParametersBecomeBool) {
    EXPECT_EQ(fixFrontFaceParameterTypes(
                  "float4 f(uint facing : SV_IsFrontFace) : SV_Target { return facing; }"),
              "float4 f(bool facing : SV_IsFrontFace) : SV_Target { return facing; }");
    std::string untouched = "float4 f(bool b : SV_IsFrontFace) : SV_Target;";
    EXPECT_EQ(fixFrontFaceParameterTypes(untouched), untouched);
}

TEST(HlslRewrites, FaceParametersBecomeASignFromTheFrontFaceBuiltIn) {
    EXPECT_EQ(fixFrontFaceParameterTypes("float4 f(V i, half s : VFACE) : SV_Target\n{\n"
                                         "    return s * i.c;\n}\nfloat4 g(float t : VFACE);"),
              "float4 f(V i, bool s_varcFrontFace : SV_IsFrontFace) : SV_Target\n{ half s = "
              "s_varcFrontFace ? 1 : -1;\n    return s * i.c;\n}\n"
              "float4 g(bool t_varcFrontFace : SV_IsFrontFace);");
}

TEST(HlslRewrites, AWrittenUniformParameterGetsALocalCopy) {
    std::string text =
        "float4 f(V i, uniform float4 _Tint : COLOR, uniform float _K) : SV_Target\n{\n"
        "    _Tint.a *= _K; i._Tint = 1;\n    return _Tint;\n}\n";
    EXPECT_EQ(rewriteHlslForGlslang(text),
              "float4 f(V i, uniform float4 _Tint : COLOR, uniform float _K) : SV_Target\n{ "
              "float4 _Tint_varcCopy = _Tint;\n"
              "    _Tint_varcCopy.a *= _K; i._Tint = 1;\n    return _Tint_varcCopy;\n}\n");
}

TEST(HlslRewrites, ReadUniformParametersPlainParametersAndPrototypesAreLeftAlone) {
    for (std::string kept :
         {"float f(uniform float a) { return a * 2; }\n", "float f(float a) { a = 2; return a; }\n",
          "float f(uniform float a[2]) { a[0] = 1; return a[0]; }\n",
          "float f(uniform float a);\nfloat g(float a) { a = 1; return a; }\n"}) {
        EXPECT_EQ(rewriteHlslForGlslang(kept), kept) << kept;
    }
}

TEST(HlslRewrites, ScalarAnyAndAllOverloadsAreDeclaredOnlyWhenAsked) {
    std::string text =
        "#line 1 0\nfloat4 f(float x : X) : SV_Target { return any(x) && all(x); }\n";
    EXPECT_EQ(rewriteHlslForGlslang(text), text);
    std::string rewritten = rewriteHlslForGlslang(text, {}, true);
    EXPECT_EQ(lineCount(rewritten), lineCount(text));
    EXPECT_EQ(rewritten.rfind("#line 1 0\nbool any(bool v) { return v; } ", 0), 0u) << rewritten;
    for (std::string overload :
         {"bool any(float v) { return v != 0; }", "bool any(int v) { return v != 0; }",
          "bool any(uint v) { return v != 0; }", "bool all(bool v) { return v; }",
          "bool all(float v) { return v != 0; }"}) {
        EXPECT_NE(rewritten.find(overload), std::string::npos) << overload;
    }
    EXPECT_NE(rewritten.find("} float4 f(float x : X) : SV_Target { return any(x) && all(x); }\n"),
              std::string::npos);
}

TEST(HlslRewrites, NoLineIsAddedOrRemoved) {
    std::string text =
        "float _T;\n\nfloat4 f() : SV_Target {\n _T = 2;\n switch (_T) {\n"
        " default: break;\n }\n return _T;\n}\n";
    std::string rewritten = rewriteHlslForGlslang(text);
    EXPECT_NE(rewritten, text);
    EXPECT_EQ(lineCount(rewritten), lineCount(text));
}

TEST(HlslRewrites, TextThatCannotBeTokenisedIsReturnedAsIs) {
    std::string text = "float _A; void f() { _A = 1; } /* unterminated";
    EXPECT_EQ(rewriteHlslForGlslang(text), text);
}

}  // namespace
}  // namespace varc::frontend
