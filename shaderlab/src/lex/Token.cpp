// SPDX-License-Identifier: Apache-2.0
// One ShaderLab token: identifier, number, string, single-character symbol, end of file or error.
#include "lex/Token.h"

#include <cstdio>

namespace varc::shaderlab {
namespace {

bool isPrintableAscii(char c) { return c >= 0x20 && c < 0x7f; }

}  // namespace

bool Token::isKeyword(std::string_view keyword) const {
    return kind == TokenKind::Identifier && equalsIgnoreAsciiCase(text, keyword);
}

std::string Token::describe() const {
    switch (kind) {
        case TokenKind::EndOfFile:
            return "end of file";
        case TokenKind::Error:
            return "an invalid token";
        case TokenKind::String:
            return "\"" + std::string(text) + "\"";
        case TokenKind::Symbol:
            if (!text.empty() && !isPrintableAscii(text[0])) {
                char buffer[16];
                std::snprintf(buffer, sizeof buffer, "byte 0x%02x",
                              static_cast<unsigned>(static_cast<unsigned char>(text[0])));
                return buffer;
            }
            break;
        case TokenKind::Identifier:
        case TokenKind::Number:
            break;
    }
    return "'" + std::string(text) + "'";
}

}  // namespace varc::shaderlab
