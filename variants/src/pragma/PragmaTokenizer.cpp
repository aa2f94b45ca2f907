// SPDX-License-Identifier: Apache-2.0
// Splits a pragma line into blank-separated tokens that carry their own source columns.
#include "pragma/PragmaTokenizer.h"

namespace varc::variants {

namespace {

constexpr uint32_t kTextOffsetFromHash = 8;  // strlen("#pragma ")

bool isBlank(char c) { return c == ' ' || c == '\t'; }

bool isIdentifierStart(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}

}  // namespace

std::vector<PragmaToken> tokenizePragma(const PragmaLine& line) {
    std::vector<PragmaToken> tokens;
    std::string_view text = line.text;
    size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && isBlank(text[i])) ++i;
        size_t start = i;
        while (i < text.size() && !isBlank(text[i])) ++i;
        if (i == start) break;
        SourceLocation location = line.location;
        if (location.column != 0) {
            location.column += kTextOffsetFromHash + static_cast<uint32_t>(start);
        }
        tokens.push_back({text.substr(start, i - start), location});
    }
    return tokens;
}

bool isAllUnderscores(std::string_view token) {
    return !token.empty() && token.find_first_not_of('_') == std::string_view::npos;
}

bool isIdentifier(std::string_view token) {
    if (token.empty() || !isIdentifierStart(token[0])) return false;
    for (char c : token) {
        if (!isIdentifierStart(c) && !(c >= '0' && c <= '9')) return false;
    }
    return true;
}

}  // namespace varc::variants
