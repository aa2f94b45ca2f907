// SPDX-License-Identifier: Apache-2.0
// Trimming whitespace off the ends of a string view.
#include "varc/core/Trim.h"

namespace varc {

std::string_view trim(std::string_view text, std::string_view whitespace) {
    const size_t first = text.find_first_not_of(whitespace);
    if (first == std::string_view::npos) return {};
    return trimRight(text.substr(first), whitespace);
}

std::string_view trimRight(std::string_view text, std::string_view whitespace) {
    const size_t last = text.find_last_not_of(whitespace);
    return last == std::string_view::npos ? std::string_view() : text.substr(0, last + 1);
}

}  // namespace varc
