// SPDX-License-Identifier: Apache-2.0
// Legacy GLSL built-ins are mapped per stage, and #line directives follow GLSL's convention.
#include <gtest/gtest.h>

#include "varc/driver/GlslLegacyPreamble.h"
#include "varc/variants/PassKeywords.h"

namespace varc::driver {
namespace {

TEST(GlslLegacyPreamble, DeclaresOnlyTheBuiltinsTheSourceMentions) {
    std::string source = "void main() { gl_Position = gl_ModelViewProjectionMatrix * gl_Vertex; }";
    std::string vertex = legacyGlslPreamble(source, Stage::Vertex);
    EXPECT_NE(vertex.find("in vec4 varc_Vertex;\n#define gl_Vertex varc_Vertex\n"),
              std::string::npos);
    EXPECT_NE(vertex.find("uniform mat4 varc_ModelViewProjectionMatrix;"), std::string::npos);
    EXPECT_EQ(vertex.find("varc_Normal"), std::string::npos);
    EXPECT_NE(vertex.find("#define varying out\n"), std::string::npos);
}

TEST(GlslLegacyPreamble, FragmentStageGetsFragColorButNoVertexAttributes) {
    std::string source = "varying vec4 p; void main() { gl_FragColor = p + gl_Vertex; }";
    std::string fragment = legacyGlslPreamble(source, Stage::Fragment);
    EXPECT_NE(fragment.find("out vec4 varc_FragColor;"), std::string::npos);
    EXPECT_EQ(fragment.find("varc_Vertex"), std::string::npos);
    EXPECT_NE(fragment.find("#define varying in\n"), std::string::npos);
}

TEST(GlslLegacyPreamble, DoesNotMatchLongerIdentifiers) {
    std::string preamble = legacyGlslPreamble("float gl_VertexCount;", Stage::Vertex);
    EXPECT_EQ(preamble.find("varc_Vertex"), std::string::npos);
}

TEST(GlslLineConvention, ShiftsDirectivesForLegacyVersions) {
    EXPECT_EQ(toGlslLineConvention("#line 12 3\nfoo\n  # line 1 0\n"),
              "#line 11 3\nfoo\n  # line 0 0\n");
}

TEST(GlslLineConvention, KeepsDirectivesFromVersion330) {
    std::string modern = "#version 330\n#line 12 3\nfoo\n";
    EXPECT_EQ(toGlslLineConvention(modern), modern);
    std::string es = "#version 300 es\n#line 12 3\n";
    EXPECT_EQ(toGlslLineConvention(es), es);
    EXPECT_EQ(toGlslLineConvention("#version 150\n#line 2 1\n"), "#version 150\n#line 1 1\n");
}

// Vulkan GLSL reads texture2D as a type; a legacy program calls it as a function.
TEST(GlslLegacyPreamble, LegacyTextureFunctionsBecomeTheGenericOnes) {
    std::string preamble = legacyGlslPreamble(
        "uniform sampler2D s; void main() { c = texture2D (s, uv) + textureCube(k, d); }",
        Stage::Fragment);
    EXPECT_NE(preamble.find("#define texture2D texture\n"), std::string::npos);
    EXPECT_NE(preamble.find("#define textureCube texture\n"), std::string::npos);
    EXPECT_EQ(preamble.find("texture2DLod"), std::string::npos);
    EXPECT_EQ(
        legacyGlslPreamble("uniform texture2D t; vec4 my_texture2D(vec2 uv);", Stage::Fragment)
            .find("texture2D"),
        std::string::npos);
}

}  // namespace
}  // namespace varc::driver
