// SPDX-License-Identifier: Apache-2.0
// Lexer: token kinds, numbers, words such as 2D, comments, locations and raw captures.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lex/Lexer.h"
#include "varc/core/Diagnostic.h"

namespace varc::shaderlab {
namespace {

constexpr FileId kFile = 3;

struct Lexed {
    std::vector<Token> tokens;  // up to and including EndOfFile or Error
    DiagnosticList diagnostics;
};

// |text| is kept alive by the caller: tokens view into it.
Lexed lexAll(const std::string& text) {
    Lexed out;
    Lexer lexer(text, kFile, out.diagnostics);
    for (size_t guard = 0; guard < text.size() + 2; ++guard) {
        out.tokens.push_back(lexer.next());
        TokenKind kind = out.tokens.back().kind;
        if (kind == TokenKind::EndOfFile || kind == TokenKind::Error) break;
    }
    return out;
}
Lexed lexAll(std::string&& text) = delete;  // tokens would view a destroyed temporary

std::vector<std::string> texts(const Lexed& lexed) {
    std::vector<std::string> out;
    for (const Token& token : lexed.tokens) out.emplace_back(token.text);
    return out;
}

std::vector<TokenKind> kinds(const Lexed& lexed) {
    std::vector<TokenKind> out;
    for (const Token& token : lexed.tokens) out.push_back(token.kind);
    return out;
}

using Texts = std::vector<std::string>;
using Kinds = std::vector<TokenKind>;

TEST(Lexer, SplitsIdentifiersStringsSymbolsAndNumbers) {
    std::string text = R"(_Tint ("Tint", Color) = (1, -0.5, .25, 1e3))";
    Lexed lexed = lexAll(text);
    EXPECT_EQ(texts(lexed), (Texts{"_Tint", "(", "Tint", ",", "Color", ")", "=", "(", "1", ",",
                                   "-0.5", ",", ".25", ",", "1e3", ")", ""}));
    EXPECT_EQ(lexed.tokens[2].kind, TokenKind::String);
    EXPECT_EQ(lexed.tokens[2].begin, 7u);  // the opening quote
    EXPECT_EQ(lexed.tokens[2].end, 13u);   // after the closing quote
    EXPECT_EQ(lexed.tokens[10].kind, TokenKind::Number);
    EXPECT_FALSE(lexed.diagnostics.hasErrors());
}

TEST(Lexer, LexesDigitLedTextureTypesAsIdentifiers) {
    std::string text = "2D 3D 2DArray 12 2E";
    Lexed lexed = lexAll(text);
    EXPECT_EQ(texts(lexed), (Texts{"2D", "3D", "2DArray", "12", "2E", ""}));
    EXPECT_EQ(kinds(lexed),
              (Kinds{TokenKind::Identifier, TokenKind::Identifier, TokenKind::Identifier,
                     TokenKind::Number, TokenKind::Identifier, TokenKind::EndOfFile}));
}

TEST(Lexer, SkipsCommentsAndCountsColumnsInBytesWithTabsAsOne) {
    std::string text = "// line\n\t/* a\n b */  Pass\n\t\t{";
    Lexed lexed = lexAll(text);
    ASSERT_EQ(texts(lexed), (Texts{"Pass", "{", ""}));
    EXPECT_EQ(lexed.tokens[0].location, (SourceLocation{kFile, 3, 8}));
    EXPECT_EQ(lexed.tokens[1].location, (SourceLocation{kFile, 4, 3}));
}

TEST(Lexer, SkipsUtf8ByteOrderMark) {
    std::string text = "\xEF\xBB\xBFShader";
    Lexed lexed = lexAll(text);
    ASSERT_EQ(texts(lexed), (Texts{"Shader", ""}));
    EXPECT_EQ(lexed.tokens[0].location.column, 4u);
}

TEST(Lexer, SkipsEveryLeadingByteOrderMark) {
    std::string text = "\xEF\xBB\xBF\xEF\xBB\xBFShader";
    Lexed lexed = lexAll(text);
    ASSERT_EQ(texts(lexed), (Texts{"Shader", ""}));
    EXPECT_EQ(lexed.tokens[0].location.column, 7u);
}

// Unity's upgrader writes `#warning Upgrade NOTE: ...` lines above `Shader`.
TEST(Lexer, AWarningLineIsReportedAndSkipped) {
    std::string text = "// note\n#warning Upgrade NOTE: unity_Scale was removed\r\nShader";
    Lexed lexed = lexAll(text);
    ASSERT_EQ(texts(lexed), (Texts{"Shader", ""}));
    ASSERT_EQ(lexed.diagnostics.diagnostics().size(), 1u);
    const Diagnostic& warning = lexed.diagnostics.diagnostics()[0];
    EXPECT_EQ(warning.severity, Severity::Warning);
    EXPECT_EQ(warning.message, "#warning Upgrade NOTE: unity_Scale was removed");
    EXPECT_EQ(warning.location, (SourceLocation{kFile, 2, 1}));
}

TEST(Lexer, ReportsUnterminatedStringAtOpeningQuote) {
    std::string text = "Name \"abc\n\"";
    Lexed lexed = lexAll(text);
    EXPECT_EQ(lexed.tokens.back().kind, TokenKind::Error);
    ASSERT_EQ(lexed.diagnostics.errorCount(), 1u);
    EXPECT_EQ(lexed.diagnostics.diagnostics()[0].message,
              "unterminated string: missing '\"' before the end of the line");
    EXPECT_EQ(lexed.diagnostics.diagnostics()[0].location, (SourceLocation{kFile, 1, 6}));
}

TEST(Lexer, ReportsUnterminatedCommentAtItsStart) {
    std::string text = "Pass\n  /* never closed";
    Lexed lexed = lexAll(text);
    EXPECT_EQ(kinds(lexed), (Kinds{TokenKind::Identifier, TokenKind::Error}));
    ASSERT_EQ(lexed.diagnostics.errorCount(), 1u);
    EXPECT_EQ(lexed.diagnostics.diagnostics()[0].message, "unterminated comment: missing '*/'");
    EXPECT_EQ(lexed.diagnostics.diagnostics()[0].location, (SourceLocation{kFile, 2, 3}));
}

TEST(Lexer, OtherBytesBecomeSymbolTokensDescribedReadably) {
    std::string text = "* \x01";
    Lexed lexed = lexAll(text);
    ASSERT_EQ(kinds(lexed), (Kinds{TokenKind::Symbol, TokenKind::Symbol, TokenKind::EndOfFile}));
    EXPECT_EQ(lexed.tokens[0].describe(), "'*'");
    EXPECT_EQ(lexed.tokens[1].describe(), "byte 0x01");
    EXPECT_EQ(lexed.tokens[2].describe(), "end of file");
}

TEST(Lexer, CapturesUntilWholeWordEndKeywordIgnoringCase) {
    std::string text = "CGPROGRAM a ENDCGX b_ENDCG endcg tail";
    DiagnosticList diagnostics;
    Lexer lexer(text, kFile, diagnostics);
    Token opening = lexer.next();
    auto captured = lexer.captureUntilWord(opening, "CGPROGRAM", "ENDCG");
    ASSERT_TRUE(captured);
    EXPECT_EQ(*captured, " a ENDCGX b_ENDCG ");
    EXPECT_EQ(lexer.next().text, "tail");
}

TEST(Lexer, CaptureAttributeStopsAtClosingBracket) {
    std::string text = "[Header(A b)] _X";
    DiagnosticList diagnostics;
    Lexer lexer(text, kFile, diagnostics);
    Token open = lexer.next();
    auto captured = lexer.captureAttribute(open);
    ASSERT_TRUE(captured);
    EXPECT_EQ(*captured, "Header(A b)");
    EXPECT_EQ(lexer.next().text, "_X");
}

}  // namespace
}  // namespace varc::shaderlab
