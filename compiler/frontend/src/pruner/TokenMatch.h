// SPDX-License-Identifier: Apache-2.0
// Small token predicates and bracket matching shared by the declaration splitter and classifier.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include "pruner/ShaderTokenizer.h"

namespace varc::frontend::pruner {

inline bool isPunct(const Token& token, char c) {
    return token.kind == TokenKind::Punct && token.text.size() == 1 && token.text[0] == c;
}

inline bool isWord(const Token& token, std::string_view word) {
    return token.kind == TokenKind::Identifier && token.text == word;
}

inline bool isOpenBracket(const Token& token) {
    return isPunct(token, '(') || isPunct(token, '[') || isPunct(token, '{');
}

inline bool isCloseBracket(const Token& token) {
    return isPunct(token, ')') || isPunct(token, ']') || isPunct(token, '}');
}

// Returns the index of the bracket closing the one at |open| (`(`, `[` or `{`), or nullopt when
// a bracket of another kind closes first or none closes before |tokens|' end.
// Example: for `( a [ b ] )` and open=0 returns 5; for `( a ]` returns nullopt.
std::optional<size_t> findClosingBracket(const std::vector<Token>& tokens, size_t open);

// Returns the first index in [|begin|, |end|) that is not inside a leading HLSL attribute
// group such as `[numthreads(8, 8, 1)]` or `[unroll]`.
size_t skipAttributes(const std::vector<Token>& tokens, size_t begin, size_t end);

// Identifiers in [|begin|, |end|) except member names after `.`, and the contents of string
// literals (HLSL attributes name functions in strings), appended to |out|.
void collectReferences(const std::vector<Token>& tokens, size_t begin, size_t end,
                       std::vector<std::string_view>& out);

}  // namespace varc::frontend::pruner
