// SPDX-License-Identifier: Apache-2.0
// One-token lookahead over the Lexer, with the "expected X, found Y" error helpers parsers share.
#include "lex/TokenCursor.h"

#include "ProgramKeyword.h"
#include "varc/core/Check.h"
#include "varc/core/Trim.h"

namespace varc::shaderlab {
const Token& TokenCursor::peek() {
    if (!mHasPeeked) {
        mPeeked = mLexer.next();
        mHasPeeked = true;
    }
    return mPeeked;
}

Token TokenCursor::next() {
    Token token = peek();
    mHasPeeked = false;
    return token;
}

bool TokenCursor::expectSymbol(char c, std::string_view context, Token* out) {
    if (!peek().isSymbol(c)) {
        return unexpected("'" + std::string(1, c) + "' " + std::string(context));
    }
    Token token = next();
    if (out) *out = token;
    return true;
}

bool TokenCursor::expect(TokenKind kind, std::string_view what, Token& out) {
    if (!peek().is(kind)) return unexpected(what);
    out = next();
    return true;
}

bool TokenCursor::unexpected(std::string_view what) {
    const Token& token = peek();
    if (token.is(TokenKind::Error)) return false;  // the lexer has reported it
    return fail(token.location, "expected " + std::string(what) + ", found " + token.describe());
}

bool TokenCursor::fail(SourceLocation location, std::string message) {
    mSink.error(location, std::move(message));
    return false;
}

BlockStep TokenCursor::blockStep(const Token& openBrace) {
    const Token& token = peek();
    if (token.isSymbol('}')) {
        next();
        return BlockStep::End;
    }
    if (token.is(TokenKind::Error)) return BlockStep::Failed;
    if (token.is(TokenKind::EndOfFile)) {
        fail(openBrace.location, "'{' opened here is never closed");
        return BlockStep::Failed;
    }
    return BlockStep::Item;
}

// Iterative, so deeply nested garbage ("{{{{...") cannot exhaust the stack.
bool TokenCursor::skipBlock(const Token& openBrace, Token* close) {
    size_t depth = 1;
    while (true) {
        const Token& token = peek();
        if (token.is(TokenKind::Error)) return false;
        if (token.is(TokenKind::EndOfFile)) {
            return fail(openBrace.location, "'{' opened here is never closed");
        }
        if (token.isSymbol('{')) ++depth;
        if (token.isSymbol('}') && --depth == 0) break;
        next();
    }
    Token last = next();
    if (close) *close = last;
    return true;
}

std::optional<ProgramBlock> TokenCursor::captureProgram(const Token& opening,
                                                        const ProgramKeyword& kind) {
    VARC_CHECK(!mHasPeeked) << "program capture after a peeked token";
    std::optional<std::string_view> text =
        mLexer.captureUntilWord(opening, kind.name, kind.endWord);
    if (!text) return std::nullopt;
    return ProgramBlock{kind.language, std::string(*text), mLexer.locationOf(opening.end)};
}

std::optional<std::string> TokenCursor::captureAttribute(const Token& opening) {
    VARC_CHECK(!mHasPeeked) << "attribute capture after a peeked token";
    std::optional<std::string_view> text = mLexer.captureAttribute(opening);
    if (!text) return std::nullopt;
    return std::string(trim(*text));
}

std::string TokenCursor::sourceBetween(const Token& first, const Token& last) const {
    return std::string(mLexer.slice(first.begin, last.end));
}

}  // namespace varc::shaderlab
