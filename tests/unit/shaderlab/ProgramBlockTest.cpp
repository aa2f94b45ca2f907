// SPDX-License-Identifier: Apache-2.0
// parseShaderLab: verbatim program blocks, their origins, END keyword matching, *INCLUDE scoping.
#include <gtest/gtest.h>

#include "ShaderLabTestSupport.h"
#include "varc/shaderlab/ShaderLabParser.h"

namespace varc::shaderlab {
namespace {

using testing::parse;
using testing::parsePassBody;
using testing::trimMargin;

TEST(ShaderLabParser, CapturesProgramTextVerbatimWithoutLexingIt) {
    // Unbalanced braces, quotes, comments and '#' inside the program must not matter.
    std::string body = "\n  #pragma vertex v // }}} \"\n  char* s = \"{\"; /* ENDCGX */\n";
    auto outcome = parsePassBody("CGPROGRAM" + body + "ENDCG");
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    const Pass& pass = outcome.shader->subShaders.at(0).passes.at(0);
    ASSERT_TRUE(pass.program);
    EXPECT_EQ(pass.program->text, body);
    EXPECT_EQ(pass.program->language, ProgramLanguage::Cg);
}

TEST(ShaderLabParser, ProgramOriginIsTheCharacterAfterTheOpeningKeyword) {
    std::string text = trimMargin(R"(
        |Shader "A" {
        |  SubShader {
        |	Pass {
        |		CGPROGRAM  #pragma target 3.0
        |		ENDCG
        |	}
        |  }
        |}
    )");
    auto outcome = parse(text);
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    const ProgramBlock& program = *outcome.shader->subShaders.at(0).passes.at(0).program;
    // Tabs count as one column: "\t\tCGPROGRAM" ends at column 11.
    EXPECT_EQ(program.origin, (SourceLocation{testing::kTestFile, 4, 12}));
    std::string line = testing::lineOf(text, program.origin.line);
    EXPECT_EQ(testing::firstLine(program.text), line.substr(program.origin.column - 1));
    EXPECT_EQ(testing::firstLine(program.text), "  #pragma target 3.0");
}

TEST(ShaderLabParser, EndKeywordMustBeAWholeWord) {
    auto outcome = parsePassBody("CGPROGRAM int ENDCGX; int xENDCG; int END_CG; ENDCG");
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    EXPECT_EQ(outcome.shader->subShaders.at(0).passes.at(0).program->text,
              " int ENDCGX; int xENDCG; int END_CG; ");
}

TEST(ShaderLabParser, EndKeywordInsideProgramCommentEndsTheBlockLikeUnity) {
    auto outcome = parsePassBody("CGPROGRAM int a; // ENDCG\n ENDCG");
    // The block ends at the commented ENDCG; the rest is ShaderLab again and is an error.
    EXPECT_FALSE(outcome.shader);
    EXPECT_EQ(outcome.firstMessage(), "unknown ShaderLab command 'ENDCG'");
    EXPECT_EQ(outcome.firstLocation(), (SourceLocation{testing::kTestFile, 2, 2}));
}

TEST(ShaderLabParser, RecognisesHlslAndGlslProgramBlocks) {
    auto hlsl = parsePassBody("HLSLPROGRAM float4 f; ENDCG ENDHLSL");
    ASSERT_TRUE(hlsl.shader) << hlsl.firstMessage();
    const ProgramBlock& h = *hlsl.shader->subShaders.at(0).passes.at(0).program;
    EXPECT_EQ(h.language, ProgramLanguage::Hlsl);
    EXPECT_EQ(h.text, " float4 f; ENDCG ");
    auto glsl = parsePassBody("GLSLPROGRAM\n#ifdef VERTEX\n#endif\nENDGLSL");
    ASSERT_TRUE(glsl.shader) << glsl.firstMessage();
    const ProgramBlock& g = *glsl.shader->subShaders.at(0).passes.at(0).program;
    EXPECT_EQ(g.language, ProgramLanguage::Glsl);
    EXPECT_EQ(g.text, "\n#ifdef VERTEX\n#endif\n");
}

TEST(ShaderLabParser, ReportsUnterminatedProgramBlockAtOpeningKeyword) {
    auto outcome = parse("Shader \"A\" { SubShader { Pass {\n  CGPROGRAM\n int a; } } }\n");
    EXPECT_FALSE(outcome.shader);
    ASSERT_EQ(outcome.diagnostics.errorCount(), 1u);
    EXPECT_EQ(outcome.firstMessage(), "unterminated CGPROGRAM block: missing ENDCG");
    EXPECT_EQ(outcome.firstLocation(), (SourceLocation{testing::kTestFile, 2, 3}));
}

TEST(ShaderLabParser, ReportsUnterminatedHlslIncludeWithItsOwnEndKeyword) {
    auto outcome = parse("Shader \"A\" { HLSLINCLUDE x ENDCG }");
    EXPECT_FALSE(outcome.shader);
    EXPECT_EQ(outcome.firstMessage(), "unterminated HLSLINCLUDE block: missing ENDHLSL");
    EXPECT_EQ(outcome.firstLocation(), (SourceLocation{testing::kTestFile, 1, 14}));
}

TEST(ShaderLabParser, RejectsSecondProgramBlockInOnePass) {
    auto outcome = parsePassBody("CGPROGRAM a ENDCG CGPROGRAM b ENDCG");
    EXPECT_FALSE(outcome.shader);
    EXPECT_EQ(outcome.firstMessage(),
              "a Pass can hold only one program block; CGPROGRAM is the second");
    EXPECT_EQ(outcome.firstLocation().column, 51u);
}

TEST(ShaderLabParser, RejectsProgramBlockOutsideAPass) {
    auto outcome = parse("Shader \"A\" { SubShader { CGPROGRAM x ENDCG } }");
    EXPECT_FALSE(outcome.shader);
    EXPECT_EQ(outcome.firstMessage(), "CGPROGRAM block must be inside a Pass");
    EXPECT_EQ(outcome.firstLocation(), (SourceLocation{testing::kTestFile, 1, 26}));
}

// A program directly in a SubShader with `#pragma surface` is a surface program: kept as a
// placeholder pass with its text, origin, pragma location and options, in file order.
TEST(ShaderLabParser, KeepsASurfaceProgramAsAPlaceholderPass) {
    auto outcome = parse(trimMargin(R"(
        |Shader "A" { CGINCLUDE shared ENDCG SubShader {
        |    Pass { CGPROGRAM p ENDCG }
        |    CGPROGRAM
        |      #  pragma surface surf Lambert vertex:vert addshadow // a comment
        |    ENDCG
        |} }
    )"));
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    const std::vector<Pass>& passes = outcome.shader->subShaders.at(0).passes;
    ASSERT_EQ(passes.size(), 2u);
    EXPECT_FALSE(passes[0].surface);
    const Pass& placeholder = passes[1];
    ASSERT_TRUE(placeholder.surface);
    EXPECT_FALSE(placeholder.program);
    EXPECT_EQ(placeholder.surface->function, "surf");
    EXPECT_EQ(placeholder.surface->lightingModel, "Lambert");
    EXPECT_EQ(placeholder.surface->options.vertexFunction, "vert");
    EXPECT_TRUE(placeholder.surface->options.addShadow);
    EXPECT_EQ(placeholder.surface->pragma, (SourceLocation{testing::kTestFile, 4, 7}));
    EXPECT_EQ(placeholder.surface->block.origin, (SourceLocation{testing::kTestFile, 3, 14}));
    ASSERT_EQ(placeholder.includeBlocks.size(), 1u);
    EXPECT_EQ(placeholder.includeBlocks[0].text, " shared ");
    EXPECT_EQ(outcome.diagnostics.errorCount(), 0u);
}

// An unknown option is an error at the option itself.
TEST(ShaderLabParser, RefusesAnUnknownSurfaceOptionAtTheOption) {
    auto outcome = parse(trimMargin(R"(
        |Shader "A" { SubShader {
        |    CGPROGRAM
        |    #pragma surface surf Lambert noforwardadd shiny
        |    ENDCG
        |} }
    )"));
    EXPECT_FALSE(outcome.shader);
    EXPECT_EQ(outcome.firstMessage(), "unknown surface shader option 'shiny'");
    EXPECT_EQ(outcome.firstLocation(), (SourceLocation{testing::kTestFile, 3, 47}));
}

// A surface program belongs directly in a SubShader; in a Category it is refused.
TEST(ShaderLabParser, RefusesASurfaceProgramOutsideASubShader) {
    auto outcome =
        parse("Shader \"A\" { Category { CGPROGRAM\n#pragma surface s Lambert\nENDCG } }");
    EXPECT_FALSE(outcome.shader);
    EXPECT_EQ(outcome.firstMessage(),
              "a surface program ('#pragma surface') must be written directly inside a SubShader");
    EXPECT_EQ(outcome.firstLocation(), (SourceLocation{testing::kTestFile, 2, 1}));
}

TEST(ShaderLabParser, CollectsIncludeBlocksInScopeInFileOrder) {
    auto outcome = parse(trimMargin(R"(
        |Shader "A" {
        |    CGINCLUDE shader ENDCG
        |    SubShader {
        |        Pass { CGINCLUDE pass1 ENDCG CGPROGRAM p1 ENDCG }
        |        HLSLINCLUDE sub1 ENDHLSL
        |        Pass { CGPROGRAM p2 ENDCG }
        |    }
        |    SubShader { Pass { CGPROGRAM p3 ENDCG } }
        |    GLSLINCLUDE late ENDGLSL
        |}
    )"));
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    auto texts = [](const Pass& pass) {
        std::vector<std::string> out;
        for (const ProgramBlock& block : pass.includeBlocks) out.push_back(block.text);
        return out;
    };
    const auto& sub0 = outcome.shader->subShaders.at(0).passes;
    const auto& sub1 = outcome.shader->subShaders.at(1).passes;
    using Texts = std::vector<std::string>;
    EXPECT_EQ(texts(sub0.at(0)), (Texts{" shader ", " pass1 ", " sub1 ", " late "}));
    EXPECT_EQ(texts(sub0.at(1)), (Texts{" shader ", " sub1 ", " late "}));
    EXPECT_EQ(texts(sub1.at(0)), (Texts{" shader ", " late "}));
    EXPECT_EQ(sub0.at(1).includeBlocks.at(1).language, ProgramLanguage::Hlsl);
    EXPECT_EQ(sub0.at(0).includeBlocks.at(0).origin, (SourceLocation{testing::kTestFile, 2, 14}));
}

TEST(ShaderLabParser, CategoryIncludeBlocksReachOnlyItsSubShaders) {
    auto outcome = parse(R"(Shader "A" {
        Category { CGINCLUDE cat ENDCG SubShader { Pass { CGPROGRAM a ENDCG } } }
        SubShader { Pass { CGPROGRAM b ENDCG } } })");
    ASSERT_TRUE(outcome.shader) << outcome.firstMessage();
    const auto& inside = outcome.shader->subShaders.at(0).passes.at(0);
    ASSERT_EQ(inside.includeBlocks.size(), 1u);
    EXPECT_EQ(inside.includeBlocks[0].text, " cat ");
    EXPECT_TRUE(outcome.shader->subShaders.at(1).passes.at(0).includeBlocks.empty());
}

}  // namespace
}  // namespace varc::shaderlab
