// SPDX-License-Identifier: Apache-2.0
// Text for self-contained HTML pages: escaping and base64 for data: URLs.
#include "varc/core/HtmlText.h"

#include <cstdint>

namespace varc {

std::string htmlEscape(std::string_view text) {
    std::string escaped;
    escaped.reserve(text.size());
    for (char c : text) {
        switch (c) {
            case '&':
                escaped += "&amp;";
                break;
            case '<':
                escaped += "&lt;";
                break;
            case '>':
                escaped += "&gt;";
                break;
            case '"':
                escaped += "&quot;";
                break;
            case '\'':
                escaped += "&#39;";
                break;
            default:
                escaped += c;
        }
    }
    return escaped;
}

std::string base64Encode(std::string_view bytes) {
    static constexpr char kAlphabet[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string encoded;
    encoded.reserve((bytes.size() + 2) / 3 * 4);
    size_t i = 0;
    for (; i + 3 <= bytes.size(); i += 3) {
        const uint32_t triple = uint32_t{static_cast<uint8_t>(bytes[i])} << 16 |
                                uint32_t{static_cast<uint8_t>(bytes[i + 1])} << 8 |
                                uint32_t{static_cast<uint8_t>(bytes[i + 2])};
        for (int shift = 18; shift >= 0; shift -= 6) encoded += kAlphabet[(triple >> shift) & 63];
    }
    const size_t rest = bytes.size() - i;
    if (rest == 0) return encoded;
    uint32_t triple = uint32_t{static_cast<uint8_t>(bytes[i])} << 16;
    if (rest == 2) triple |= uint32_t{static_cast<uint8_t>(bytes[i + 1])} << 8;
    encoded += kAlphabet[(triple >> 18) & 63];
    encoded += kAlphabet[(triple >> 12) & 63];
    encoded += rest == 2 ? kAlphabet[(triple >> 6) & 63] : '=';
    encoded += '=';
    return encoded;
}

}  // namespace varc
