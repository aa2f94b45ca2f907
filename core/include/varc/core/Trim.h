// SPDX-License-Identifier: Apache-2.0
// Trimming whitespace off the ends of a string view.
#pragma once

#include <string_view>

namespace varc {

// The C locale's isspace set: space, \t, \n, \v, \f, \r.
inline constexpr std::string_view kAsciiWhitespace = " \t\n\v\f\r";

// |text| without the leading and trailing characters that are in |whitespace| (by default every
// ASCII whitespace character); a view into |text|. trim("  a b \n") == "a b"; trim(" ") == "".
std::string_view trim(std::string_view text, std::string_view whitespace = kAsciiWhitespace);

// |text| without the trailing characters that are in |whitespace|. trimRight(" a \r") == " a".
std::string_view trimRight(std::string_view text, std::string_view whitespace = kAsciiWhitespace);

}  // namespace varc
