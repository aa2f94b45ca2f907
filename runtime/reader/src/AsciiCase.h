// SPDX-License-Identifier: Apache-2.0
// ASCII case-insensitive comparison, for tag names and values (Unity compares them so).
#pragma once

#include <string_view>

namespace varc::runtime::detail {

inline bool equalsIgnoreAsciiCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i) {
        char x = a[i], y = b[i];
        if (x >= 'A' && x <= 'Z') x = static_cast<char>(x - 'A' + 'a');
        if (y >= 'A' && y <= 'Z') y = static_cast<char>(y - 'A' + 'a');
        if (x != y) return false;
    }
    return true;
}

}  // namespace varc::runtime::detail
