// SPDX-License-Identifier: Apache-2.0
// parseShaderLab: error messages and their file:line:col for malformed shader files.
#include <gtest/gtest.h>

#include "ShaderLabTestSupport.h"
#include "varc/shaderlab/ShaderLabParser.h"

namespace varc::shaderlab {
namespace {

using testing::kTestFile;
using testing::parse;
using testing::trimMargin;

// Expects |text| to fail with exactly one error |message| at |line|:|column|.
void expectSingleError(std::string_view text, std::string_view message, uint32_t line,
                       uint32_t column) {
    auto outcome = parse(text);
    EXPECT_FALSE(outcome.shader) << text;
    ASSERT_EQ(outcome.diagnostics.errorCount(), 1u) << text;
    const Diagnostic& diagnostic = outcome.diagnostics.diagnostics()[0];
    EXPECT_EQ(diagnostic.severity, Severity::Error);
    EXPECT_EQ(diagnostic.message, message) << text;
    EXPECT_EQ(diagnostic.location, (SourceLocation{kTestFile, line, column})) << text;
}

TEST(ShaderLabDiagnostics, ReportsUnexpectedTokenAfterShaderName) {
    expectSingleError("Shader \"A\"\n  Pass { }", "expected '{' after Shader name, found 'Pass'", 2,
                      3);
}

TEST(ShaderLabDiagnostics, ReportsMissingShaderKeywordAndName) {
    expectSingleError("", "expected 'Shader' at the start of the file, found end of file", 1, 1);
    expectSingleError("  SubShader {}",
                      "expected 'Shader' at the start of the file, found "
                      "'SubShader'",
                      1, 3);
    expectSingleError("Shader {", "expected a shader name string after Shader, found '{'", 1, 8);
}

TEST(ShaderLabDiagnostics, ReportsNeverClosedBraceAtTheOpeningBrace) {
    std::string text = trimMargin(R"(
        |Shader "A" {
        |    SubShader {
        |        Pass {
        |            Cull Off
        |    }
        |}
    )");
    expectSingleError(text, "'{' opened here is never closed", 1, 12);
    expectSingleError("Shader \"A\" { SubShader { Pass { Material { Diffuse (1,1,1,1) ",
                      "'{' opened here is never closed", 1, 42);
}

TEST(ShaderLabDiagnostics, ReportsUnterminatedStringAndComment) {
    expectSingleError("Shader \"A { }\n",
                      "unterminated string: missing '\"' before the end of "
                      "the line",
                      1, 8);
    expectSingleError("Shader \"A\" { /* comment\n }", "unterminated comment: missing '*/'", 1, 14);
}

TEST(ShaderLabDiagnostics, ReportsTextAfterTheShaderBlock) {
    expectSingleError("Shader \"A\" { }\n}",
                      "expected end of file after the Shader block, found "
                      "'}'",
                      2, 1);
}

TEST(ShaderLabDiagnostics, ReportsNonCommandTokenWhereCommandExpected) {
    expectSingleError("Shader \"A\" { SubShader { \"Pass\" } }",
                      "expected a command or '}' in SubShader, found \"Pass\"", 1, 26);
    expectSingleError("Shader \"A\" { SubShader { Pass { 42 } } }",
                      "expected a command or '}' in Pass, found '42'", 1, 33);
}

TEST(ShaderLabDiagnostics, ReportsPassOutsideSubShaderAsUnknownCommand) {
    expectSingleError("Shader \"A\" { Pass {} }", "unknown ShaderLab command 'Pass'", 1, 14);
}

TEST(ShaderLabDiagnostics, ReportsMalformedTagsAndLod) {
    expectSingleError("Shader \"A\" { SubShader { Tags { Queue = \"x\" } } }",
                      "expected a tag name string or '}' in Tags, found 'Queue'", 1, 33);
    expectSingleError("Shader \"A\" { SubShader { Tags { \"Queue\" \"x\" } } }",
                      "expected '=' after tag name \"Queue\", found \"x\"", 1, 41);
    expectSingleError("Shader \"A\" { SubShader { LOD 1.5 } }",
                      "invalid LOD '1.5'; expected an integer", 1, 30);
}

TEST(ShaderLabDiagnostics, ReportsOnlyTheFirstError) {
    auto outcome = parse("Shader \"A\" { SubShader { Foo Bar Pass { Baz } } }");
    EXPECT_FALSE(outcome.shader);
    ASSERT_EQ(outcome.diagnostics.diagnostics().size(), 1u);
    EXPECT_EQ(outcome.firstMessage(), "unknown ShaderLab command 'Foo'");
}

}  // namespace
}  // namespace varc::shaderlab
