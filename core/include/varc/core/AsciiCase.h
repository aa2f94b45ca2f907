// SPDX-License-Identifier: Apache-2.0
// ASCII case folding. Unity compares ShaderLab keywords, tag names and values, semantics and
// light types without regard to ASCII case; these never fold non-ASCII bytes (so UTF-8 text
// passes through unchanged) and never depend on the C locale, unlike std::tolower.
#pragma once

#include <string>
#include <string_view>

namespace varc {

constexpr char toAsciiLower(char c) {
    return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
}
constexpr char toAsciiUpper(char c) {
    return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c;
}

// equalsIgnoreAsciiCase("ForwardBase", "forwardbase") == true; ("Ä", "ä") == false.
constexpr bool equalsIgnoreAsciiCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        if (toAsciiLower(a[i]) != toAsciiLower(b[i])) return false;
    }
    return true;
}

// toAsciiLower("llvmPipe") == "llvmpipe".
inline std::string toAsciiLower(std::string_view text) {
    std::string result(text);
    for (char& c : result) c = toAsciiLower(c);
    return result;
}

// toAsciiUpper("texcoord0") == "TEXCOORD0".
inline std::string toAsciiUpper(std::string_view text) {
    std::string result(text);
    for (char& c : result) c = toAsciiUpper(c);
    return result;
}

}  // namespace varc
