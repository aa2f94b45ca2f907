// SPDX-License-Identifier: Apache-2.0
// Levenshtein distance and "did you mean" suggestions for misspelled pragma names.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace varc::variants {

// Insertions, deletions and substitutions needed to turn |a| into |b|.
// Example: editDistance("fwdadd_fullshadow", "fwdadd_fullshadows") == 1.
size_t editDistance(std::string_view a, std::string_view b);

// The candidate nearest to |name| if it is close enough to be a plausible typo: at most
// max(1, min(3, |name|/3)) edits. Ties go to the earlier candidate. nullopt otherwise.
std::optional<std::string> suggestName(std::string_view name,
                                       const std::vector<std::string>& candidates);

}  // namespace varc::variants
