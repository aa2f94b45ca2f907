// SPDX-License-Identifier: Apache-2.0
// Small token predicates and bracket matching shared by the declaration splitter and classifier.
#include "pruner/TokenMatch.h"

namespace varc::frontend::pruner {
namespace {

char closerOf(const Token& open) {
    switch (open.text[0]) {
        case '(':
            return ')';
        case '[':
            return ']';
        default:
            return '}';
    }
}

}  // namespace

std::optional<size_t> findClosingBracket(const std::vector<Token>& tokens, size_t open) {
    std::vector<char> expected{closerOf(tokens[open])};
    for (size_t i = open + 1; i < tokens.size(); ++i) {
        const Token& token = tokens[i];
        if (isOpenBracket(token)) {
            expected.push_back(closerOf(token));
        } else if (isCloseBracket(token)) {
            if (token.text[0] != expected.back()) return std::nullopt;
            expected.pop_back();
            if (expected.empty()) return i;
        }
    }
    return std::nullopt;
}

size_t skipAttributes(const std::vector<Token>& tokens, size_t begin, size_t end) {
    size_t i = begin;
    while (i < end && isPunct(tokens[i], '[')) {
        const std::optional<size_t> close = findClosingBracket(tokens, i);
        if (!close || *close >= end) return i;
        i = *close + 1;
    }
    return i;
}

void collectReferences(const std::vector<Token>& tokens, size_t begin, size_t end,
                       std::vector<std::string_view>& out) {
    for (size_t i = begin; i < end; ++i) {
        // HLSL attributes name functions in strings: [patchconstantfunc("PatchConstants")].
        if (tokens[i].kind == TokenKind::String && tokens[i].text.size() > 2) {
            out.push_back(tokens[i].text.substr(1, tokens[i].text.size() - 2));
            continue;
        }
        if (tokens[i].kind != TokenKind::Identifier) continue;
        if (i > 0 && isPunct(tokens[i - 1], '.')) continue;
        out.push_back(tokens[i].text);
    }
}

}  // namespace varc::frontend::pruner
