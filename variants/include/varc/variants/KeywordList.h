// SPDX-License-Identifier: Apache-2.0
// How diagnostics and reports spell a variant's keywords: one spelling for the whole code base.
#pragma once

#include <string>
#include <vector>

#include "varc/core/JoinWords.h"

namespace varc::variants {

// What a variant without keywords is called in messages.
inline constexpr const char* kNoKeywordsText = "<no keywords>";

// joinKeywords({"POINT", "SHADOWS_CUBE"}) == "POINT SHADOWS_CUBE"; joinKeywords({}) ==
// "<no keywords>".
inline std::string joinKeywords(const std::vector<std::string>& names) {
    return names.empty() ? std::string(kNoKeywordsText) : joinWords(names);
}

}  // namespace varc::variants
