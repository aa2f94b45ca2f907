// SPDX-License-Identifier: Apache-2.0
// Picks the variant to use for a requested keyword set: exact, closest, first or strict.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "varc/variants/VariantKey.h"

namespace varc::variants {

enum class SelectionPolicy {
    Exact,    // only an exact match; no fallback
    Closest,  // default: max |V ∩ R|, then min |V \ R|, then earliest (docs/KEYWORDS.md §8)
    First,    // Unity 5.x: exact match, else the first variant
    Strict,   // exact match, else an error listing the nearest variants (Unity 2022 strict)
};

// Parses "exact|closest|first|strict".
std::optional<SelectionPolicy> parseSelectionPolicy(std::string_view name);
const char* toString(SelectionPolicy policy);

struct Selection {
    std::optional<size_t> index;   // into the available list; nullopt = no variant
    bool exact = false;
    std::vector<size_t> nearest;   // for Strict/Exact misses: up to 3 closest, best first
};

// |available| is in enumeration order. |requested| must already be restricted to the pass's
// declared keywords (KeywordTable::keyOf does that). Pure; allocates only for misses.
Selection selectVariant(std::span<const VariantKey> available, const VariantKey& requested,
                        SelectionPolicy policy);

}  // namespace varc::variants
