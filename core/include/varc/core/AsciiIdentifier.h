// SPDX-License-Identifier: Apache-2.0
// Character classes of C-like source text (HLSL, GLSL, preprocessor lines), locale-free.
#pragma once

namespace varc {

constexpr bool isAsciiIdentifierStart(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
constexpr bool isAsciiIdentifierChar(char c) {
    return isAsciiIdentifierStart(c) || (c >= '0' && c <= '9');
}
// Blanks inside one line: space, tab, carriage return, form feed, vertical tab (not '\n').
constexpr bool isAsciiLineBlank(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

}  // namespace varc
