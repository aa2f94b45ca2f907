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

}  // namespace varc::frontend::hlsl
