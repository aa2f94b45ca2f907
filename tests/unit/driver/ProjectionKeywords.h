// SPDX-License-Identifier: Apache-2.0
// The four keywords the keyword-projection tests use, and variant keys spelled by their names.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "varc/variants/VariantKey.h"

namespace varc::driver::testing {

inline const std::vector<std::string> kKeywords = {"A", "B", "C", "D"};  // sorted: bit = index

// The key with the keywords |names| spells on ("AC": A and C).
inline variants::VariantKey keyOf(std::string_view names) {
    variants::VariantKey key;
    for (size_t k = 0; k < kKeywords.size(); ++k)
        if (names.find(kKeywords[k]) != std::string_view::npos) key.set(k);
    return key;
}

inline std::string namesOf(const variants::VariantKey& key) {
    std::string names;
    for (size_t k = 0; k < kKeywords.size(); ++k)
        if (key.test(k)) names += kKeywords[k];
    return names;
}

}  // namespace varc::driver::testing
