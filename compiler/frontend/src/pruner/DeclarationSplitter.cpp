// SPDX-License-Identifier: Apache-2.0
// Splits the token stream of a preprocessed program into top-level declarations.
#include "pruner/DeclarationSplitter.h"

#include <array>
#include <string_view>

#include "pruner/TokenMatch.h"

namespace varc::frontend::pruner {
namespace {

// Identifiers followed by `(` that do not name a function: `layout(std140)`,
// `register(b0)`, `packoffset(c1)`, `subroutine(...)`.
bool isQualifierCall(std::string_view word) {
    return word == "layout" || word == "register" || word == "packoffset" || word == "subroutine";
}

bool isHlslBlockKeyword(std::string_view word) {
    constexpr std::array<std::string_view, 8> kKeywords = {"cbuffer",     "tbuffer",    "namespace",
                                                           "class",       "interface",  "technique",
                                                           "technique10", "technique11"};
    for (const std::string_view keyword : kKeywords) {
        if (word == keyword) return true;
    }
    return false;
}

}  // namespace

std::optional<std::vector<DeclarationSpan>> DeclarationSplitter::split() const {
    std::vector<DeclarationSpan> spans;
    size_t begin = 0;
    while (begin < mTokens.size()) {
        std::optional<DeclarationSpan> span = splitOne(begin);
        if (!span) return std::nullopt;
        begin = span->end;
        spans.push_back(*span);
    }
    return spans;
}

std::optional<DeclarationSpan> DeclarationSplitter::splitOne(size_t begin) const {
    DeclarationSpan span;
    span.begin = begin;
    for (size_t i = begin; i < mTokens.size(); ++i) {
        const Token& token = mTokens[i];
        if (isCloseBracket(token)) return std::nullopt;
        if (isPunct(token, ';')) {
            span.end = i + 1;
            return span;
        }
        if (isPunct(token, '=') && !span.firstAssign) span.firstAssign = i;
        if (isWord(token, "struct")) span.hasStruct = true;
        if (!isOpenBracket(token)) continue;

        const std::optional<size_t> close = findClosingBracket(mTokens, i);
        if (!close) return std::nullopt;
        if (isPunct(token, '(') && !span.head && !span.firstAssign && i > begin &&
            mTokens[i - 1].kind == TokenKind::Identifier && !isQualifierCall(mTokens[i - 1].text)) {
            span.head = i - 1;
        }
        if (isPunct(token, '{')) {
            if (!span.firstBrace) span.firstBrace = i;
            const bool functionBody = span.head && !span.hasStruct && !span.firstAssign;
            if (functionBody || endsAtClosingBrace(begin)) {
                span.end = *close + 1;
                if (!functionBody && span.end < mTokens.size() && isPunct(mTokens[span.end], ';')) {
                    ++span.end;
                }
                return span;
            }
        }
        i = *close;
    }
    return std::nullopt;
}

bool DeclarationSplitter::endsAtClosingBrace(size_t begin) const {
    if (mDialect != ShaderDialect::Hlsl) return false;
    const size_t first = skipAttributes(mTokens, begin, mTokens.size());
    return first < mTokens.size() && mTokens[first].kind == TokenKind::Identifier &&
           isHlslBlockKeyword(mTokens[first].text);
}

}  // namespace varc::frontend::pruner
