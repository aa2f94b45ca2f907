// SPDX-License-Identifier: Apache-2.0
// findUnnamedEntryParameter: the entry-point shapes glslang crashes on, and the ones it does not.
#include <gtest/gtest.h>

#include "varc/frontend/EntryPointCheck.h"

namespace varc::frontend {
namespace {

std::optional<UnnamedParameter> check(const std::string& text, const char* entry = "vert") {
    return findUnnamedEntryParameter(text, entry);
}

TEST(EntryPointCheck, FindsATypeWithoutAName) {
    auto unnamed = check("float4 vert(float4 : POSITION) : SV_POSITION { return 0; }");
    ASSERT_TRUE(unnamed);
    EXPECT_EQ(unnamed->index, 1u);
    EXPECT_EQ(unnamed->text, "float4 : POSITION");
    ASSERT_TRUE(check("void vert(int){}"));
    auto second = check("void vert(float4 p : POSITION, uint) {}");
    ASSERT_TRUE(second);
    EXPECT_EQ(second->index, 2u);
}

TEST(EntryPointCheck, ModifiersTemplatesAndArraysAreNotNames) {
    EXPECT_TRUE(check("void vert(in float4) {}"));
    EXPECT_TRUE(check("void vert(inout TriangleStream<g2f>) {}"));
    EXPECT_TRUE(check("void vert(triangle v2g[3]) {}"));
}

TEST(EntryPointCheck, AcceptsWhatShadersReallyWrite) {
    EXPECT_FALSE(check("float4 vert(float4 p : POSITION) : SV_POSITION { return p; }"));
    EXPECT_FALSE(check("v2f vert(appdata_base v) { v2f o; return o; }"));
    EXPECT_FALSE(check("void vert(in float4 p : POSITION, out float4 o : SV_POSITION) {}"));
    EXPECT_FALSE(
        check("[maxvertexcount(3)] void vert(triangle v2g IN[3], "
              "inout TriangleStream<g2f> stream) {}"));
    EXPECT_FALSE(
        check("hs_out vert(InputPatch<v2h, 3> patch, uint id : SV_OutputControlPointID) {}"));
    EXPECT_FALSE(check("float4 vert(float4 p : POSITION, uniform float s = 1.0) : SV_POSITION {}"));
    EXPECT_FALSE(check("float4 vert() : SV_POSITION { return 0; }"));
    EXPECT_FALSE(check("float4 vert(void) : SV_POSITION { return 0; }"));
}

TEST(EntryPointCheck, OnlyTheDefinitionOfTheEntryPointCounts) {
    // A prototype (ends with ';'), a call, and another function are not the definition.
    EXPECT_FALSE(check("float4 vert(float4);\nfloat4 vert(float4 p) { return p; }"));
    EXPECT_FALSE(
        check("float4 other(float4) { return 0; }\nfloat4 vert(float4 p) { return other(p); }"));
    EXPECT_FALSE(check("float4 frag(float4 p) { return vert(p); }"));
    EXPECT_FALSE(check("no entry point here"));
}

TEST(EntryPointCheck, LocatesTheParameterThroughLineDirectives) {
    auto unnamed = check("#line 1 0\nfloat x;\n#line 40 3\nfloat2 y;\nfloat4 vert(\n  float4) {}");
    ASSERT_TRUE(unnamed);
    EXPECT_EQ(unnamed->file, 3u);
    EXPECT_EQ(unnamed->line, 42u);  // line 40 is "float2 y;", 41 "float4 vert(", 42 "  float4) {}"
}

}  // namespace
}  // namespace varc::frontend
