// SPDX-License-Identifier: Apache-2.0
// One ShaderLab token: identifier, number, string, single-character symbol, end of file or error.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "varc/core/AsciiCase.h"
#include "varc/core/SourceLocation.h"

namespace varc::shaderlab {

enum class TokenKind { Identifier, Number, String, Symbol, EndOfFile, Error };

struct Token {
    TokenKind kind = TokenKind::EndOfFile;
    // Identifier/number/symbol as written; a string's contents without the quotes.
    std::string_view text;
    SourceLocation location;  // of the first character (the opening quote for strings)
    size_t begin = 0;         // byte offsets into the file; [begin, end) includes quotes
    size_t end = 0;

    // True for an identifier equal to |keyword| ignoring ASCII case: isKeyword("pass").
    bool isKeyword(std::string_view keyword) const;
    // True for the symbol token |c|, e.g. isSymbol('{').
    bool isSymbol(char c) const {
        return kind == TokenKind::Symbol && text.size() == 1 && text[0] == c;
    }
    bool is(TokenKind k) const { return kind == k; }

    // How the token reads in a message: 'Pass', "a string", end of file, byte 0x01.
    std::string describe() const;
};

}  // namespace varc::shaderlab
