// SPDX-License-Identifier: Apache-2.0
// The shared base of the HLSL rewrites: token helpers and applying the collected edits.
#include "HlslRewrite.h"

#include <algorithm>

namespace varc::frontend::hlsl {

using pruner::TokenKind;

std::string RewriteState::apply(std::string_view text) {
    if (insertions.empty() && replacements.empty()) return std::string(text);
    for (const Insertion& insertion : insertions) {
        replacements.push_back({insertion.offset, 0, insertion.text});
    }
    std::stable_sort(
        replacements.begin(), replacements.end(),
        [](const Replacement& a, const Replacement& b) { return a.offset > b.offset; });
    std::string result(text);
    for (const Replacement& r : replacements) result.replace(r.offset, r.length, r.text);
    return result;
}

HlslRewrite::HlslRewrite(RewriteState& state)
    : mTokenizer(state.tokenizer),
      mTokens(state.tokenizer.tokens()),
      mDepth(state.depth),
      mInDeclarationBody(state.inDeclarationBody),
      mCbufferBodies(state.cbufferBodies),
      mInsertions(state.insertions),
      mReplacements(state.replacements) {}

bool HlslRewrite::is(size_t i, char c) const {
    return i < mTokens.size() && mTokens[i].kind == TokenKind::Punct &&
           mTokens[i].text.size() == 1 && mTokens[i].text[0] == c;
}

bool HlslRewrite::isWord(size_t i, std::string_view word) const {
    return i < mTokens.size() && mTokens[i].kind == TokenKind::Identifier &&
           mTokens[i].text == word;
}

size_t HlslRewrite::matching(size_t open) const {
    char opener = mTokens[open].text[0];
    char closer = opener == '(' ? ')' : opener == '[' ? ']' : '}';
    int depth = 0;
    for (size_t i = open; i < mTokens.size(); ++i) {
        if (is(i, opener)) ++depth;
        if (is(i, closer) && --depth == 0) return i;
    }
    return std::string::npos;
}

bool HlslRewrite::isWrite(size_t i) const {
    if (i >= 2 && (is(i - 1, '+') || is(i - 1, '-')) && is(i - 2, mTokens[i - 1].text[0]) &&
        adjacent(i - 2, i - 1)) {
        return true;
    }
    size_t j = i + 1;
    while (j < mTokens.size()) {
        if (is(j, '.') && j + 1 < mTokens.size() && mTokens[j + 1].kind == TokenKind::Identifier) {
            j += 2;
        } else if (is(j, '[')) {
            size_t close = matching(j);
            if (close == std::string::npos) return false;
            j = close + 1;
        } else {
            break;
        }
    }
    if (j >= mTokens.size() || mTokens[j].kind != TokenKind::Punct) return false;
    char c = mTokens[j].text[0];
    bool next = j + 1 < mTokens.size() && adjacent(j, j + 1);
    if (c == '=') return !(next && is(j + 1, '='));
    if ((c == '+' || c == '-') && next && is(j + 1, c)) return true;
    if (std::string_view("+-*/%&|^").find(c) != std::string_view::npos) {
        return next && is(j + 1, '=');
    }
    if ((c == '<' || c == '>') && next && is(j + 1, c)) {
        return j + 2 < mTokens.size() && adjacent(j + 1, j + 2) && is(j + 2, '=');
    }
    return false;
}

size_t HlslRewrite::functionBodyAfterParameter(size_t i) const {
    int depth = 0;
    size_t j = i;
    for (; j < mTokens.size(); ++j) {
        if (is(j, '(')) ++depth;
        if (is(j, ')') && --depth < 0) break;
        if (depth == 0 && (is(j, ';') || is(j, '{'))) return std::string::npos;
    }
    for (++j; j < mTokens.size(); ++j) {
        if (is(j, '{')) return j;
        if (is(j, ';') || is(j, '(') || is(j, '}')) return std::string::npos;
    }
    return std::string::npos;
}

}  // namespace varc::frontend::hlsl
