// SPDX-License-Identifier: Apache-2.0
// Joins words into one line of text.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace varc {

// joinWords({"a", "b", "c"}) == "a b c"; joinWords({"x", "y"}, ", ") == "x, y"; {} -> "".
inline std::string joinWords(const std::vector<std::string>& words,
                             std::string_view separator = " ") {
    std::string text;
    for (size_t i = 0; i < words.size(); ++i) {
        if (i) text += separator;
        text += words[i];
    }
    return text;
}

}  // namespace varc
