// SPDX-License-Identifier: Apache-2.0
// Splits ShaderLab text into tokens and captures program blocks and attributes verbatim.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

#include "lex/LineIndex.h"
#include "lex/Token.h"
#include "varc/core/Diagnostic.h"

namespace varc::shaderlab {

// Tokens: identifiers ([A-Za-z_][A-Za-z0-9_]*, and digit-led words such as `2D`, `2DArray`),
// numbers (`-1`, `.5`, `1e3`), double-quoted strings (single line, no escapes), and every other
// byte as a one-character symbol. `//` and `/* */` comments and whitespace are skipped. A UTF-8
// byte order mark at the start is skipped.
//
// Lexical errors (unterminated string or comment, unterminated raw capture) are reported to the
// sink once; the lexer then returns only Error tokens.
class Lexer {
public:
    Lexer(std::string_view text, FileId file, DiagnosticSink& sink);

    // The next token, or EndOfFile (repeatedly) at the end, or Error after a lexical error.
    Token next();

    // Captures the raw text from the current position (just after |opening|) up to the first
    // whole-word, ASCII-case-insensitive occurrence of |endWord|, and continues after it.
    // On failure reports "unterminated <|blockName|> block: missing <|endWord|>" at |opening|
    // and returns nullopt. Example: after CGPROGRAM in "CGPROGRAM int a; ENDCG" -> " int a; ".
    std::optional<std::string_view> captureUntilWord(const Token& opening,
                                                     std::string_view blockName,
                                                     std::string_view endWord);

    // Captures the raw text from the current position (just after |opening|, a '[') up to the
    // next ']' on the same line, and continues after it. Reports
    // "unterminated attribute: missing ']'" at |opening| and returns nullopt when there is none.
    std::optional<std::string_view> captureAttribute(const Token& opening);

    SourceLocation locationOf(size_t offset) const { return mLines.locationOf(offset); }
    // Source text [begin, end) as written.
    std::string_view slice(size_t begin, size_t end) const;

private:
    bool skipTrivia();
    bool skipBlockComment();
    void skipWarningLine();
    Token lexString();
    Token lexNumberOrWord();
    Token lexWord(size_t begin);
    bool startsNumber() const;
    size_t skipDigits(size_t pos) const;
    Token make(TokenKind kind, size_t begin, size_t end, std::string_view text) const;
    Token fail(size_t at, std::string message);
    bool isWholeWordAt(size_t pos, std::string_view word) const;
    char at(size_t pos) const { return pos < mText.size() ? mText[pos] : '\0'; }

    std::string_view mText;
    DiagnosticSink& mSink;
    LineIndex mLines;
    size_t mPos = 0;
    bool mFailed = false;
};

}  // namespace varc::shaderlab
