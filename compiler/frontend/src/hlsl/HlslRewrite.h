// SPDX-License-Identifier: Apache-2.0
// The shared base of the HLSL rewrites: a token view of one program and the edits they collect.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "../pruner/ShaderTokenizer.h"

namespace varc::frontend::hlsl {

// Text inserted at an offset of the original text; applied from the back.
struct Insertion {
    size_t offset = 0;
    std::string text;
    bool operator<(const Insertion& other) const { return offset < other.offset; }
};

// Text replacing |length| characters at an offset of the original text.
struct Replacement {
    size_t offset = 0, length = 0;
    std::string text;
};

// What the rewrites of one program share: the tokens, what DeclarationBodyScan learns about
// them, and the edits collected so far.
struct RewriteState {
    explicit RewriteState(const pruner::ShaderTokenizer& tokens) : tokenizer(tokens) {}

    // |text| (the tokenised text) with every edit applied, insertions and replacements at one
    // offset in the order they were collected; |text| itself when there is none.
    std::string apply(std::string_view text);

    const pruner::ShaderTokenizer& tokenizer;
    std::vector<int> depth;               // brace depth of every token (a brace counts inside)
    std::vector<bool> inDeclarationBody;  // whether a token lies in a struct or cbuffer body
    std::vector<std::pair<size_t, size_t>> cbufferBodies;  // file-scope cbuffer '{' and '}'
    std::vector<Insertion> insertions;
    std::vector<Replacement> replacements;
};

// Base of one rewrite: token helpers over a RewriteState, whose edits the rewrite appends to.
// Every rewrite keeps the line structure: it never adds or removes a line break, so `#line`
// mappings still hold.
class HlslRewrite {
protected:
    explicit HlslRewrite(RewriteState& state);

    size_t offsetOf(size_t i) const { return mTokenizer.offsetOf(mTokens[i]); }
    size_t endOf(size_t i) const { return offsetOf(i) + mTokens[i].text.size(); }
    bool adjacent(size_t a, size_t b) const { return endOf(a) == offsetOf(b); }
    bool is(size_t i, char c) const;
    bool isWord(size_t i, std::string_view word) const;
    // The index of the token closing the bracket opened at |open|, or npos.
    size_t matching(size_t open) const;
    // Whether the name at |i| is written there: `x = `, `x op= `, `x.yz = `, `x[i] = `, `x++`,
    // `++x` (not `x == `, `x <= `, `x << 1`).
    bool isWrite(size_t i) const;
    // The '{' opening the body of the function whose parameter list holds token |i|, or npos
    // (a prototype, or not a parameter at all).
    size_t functionBodyAfterParameter(size_t i) const;

    const pruner::ShaderTokenizer& mTokenizer;
    const std::vector<pruner::Token>& mTokens;
    std::vector<int>& mDepth;
    std::vector<bool>& mInDeclarationBody;
    std::vector<std::pair<size_t, size_t>>& mCbufferBodies;
    std::vector<Insertion>& mInsertions;
    std::vector<Replacement>& mReplacements;
};

}  // namespace varc::frontend::hlsl
