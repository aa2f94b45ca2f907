// SPDX-License-Identifier: Apache-2.0
// One-token lookahead over the Lexer, with the "expected X, found Y" error helpers parsers share.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "lex/Lexer.h"
#include "lex/Token.h"
#include "varc/core/Diagnostic.h"
#include "varc/shaderlab/ShaderAst.h"

namespace varc::shaderlab {

struct ProgramKeyword;

// What the next token means inside a `{ ... }` block being parsed item by item.
enum class BlockStep { Item, End, Failed };

// All parse functions return false after an error has been reported (by them or the lexer);
// callers stop and propagate the false, so exactly the first error is reported.
class TokenCursor {
public:
    TokenCursor(Lexer& lexer, DiagnosticSink& sink) : mLexer(lexer), mSink(sink) {}

    const Token& peek();
    Token next();

    // Consumes the symbol |c| or reports "expected 'c' <|context|>, found <next>".
    // Example: expectSymbol('{', "after Shader name") -> "expected '{' after Shader name, found
    // 'Pass'". On success stores the token in |out| when given.
    bool expectSymbol(char c, std::string_view context, Token* out = nullptr);
    // Consumes a token of |kind| into |out| or reports "expected <|what|>, found <next>".
    bool expect(TokenKind kind, std::string_view what, Token& out);
    // Reports "expected <|what|>, found <next>" (unless the lexer already reported) and
    // returns false.
    bool unexpected(std::string_view what);
    // Reports |message| at |location| and returns false.
    bool fail(SourceLocation location, std::string message);

    // Inside a block opened by |openBrace|: consumes '}' and returns End, returns Item when an
    // item follows, or reports "'{' opened here is never closed" at |openBrace| at end of file.
    BlockStep blockStep(const Token& openBrace);
    // Skips tokens up to and including the '}' matching |openBrace| (nesting allowed), which
    // is stored in |close| when given.
    bool skipBlock(const Token& openBrace, Token* close = nullptr);

    // Captures the program text after |opening| (just consumed, nothing peeked) up to its END
    // keyword; see Lexer::captureUntilWord.
    std::optional<ProgramBlock> captureProgram(const Token& opening, const ProgramKeyword& kind);
    // Captures a `[...]` attribute's text after |opening| (a just-consumed '['), trimmed.
    std::optional<std::string> captureAttribute(const Token& opening);

    // Where errors go, for helpers that report without a token (surface pragma options).
    DiagnosticSink& sink() { return mSink; }

    // Source text from |first|'s start to |last|'s end, as written.
    std::string sourceBetween(const Token& first, const Token& last) const;

private:
    Lexer& mLexer;
    DiagnosticSink& mSink;
    Token mPeeked;
    bool mHasPeeked = false;
};

}  // namespace varc::shaderlab
