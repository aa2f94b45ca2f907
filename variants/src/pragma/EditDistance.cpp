// SPDX-License-Identifier: Apache-2.0
// Levenshtein distance and "did you mean" suggestions for misspelled pragma names.
#include "pragma/EditDistance.h"

#include <algorithm>
#include <numeric>

namespace varc::variants {

// Two-row dynamic programme: row[j] = distance between a[0..i) and b[0..j).
size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<size_t> previous(b.size() + 1);
    std::vector<size_t> current(b.size() + 1);
    std::iota(previous.begin(), previous.end(), size_t{0});
    for (size_t i = 1; i <= a.size(); ++i) {
        current[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
        }
        std::swap(previous, current);
    }
    return previous[b.size()];
}

std::optional<std::string> suggestName(std::string_view name,
                                       const std::vector<std::string>& candidates) {
    size_t limit = std::max<size_t>(1, std::min<size_t>(3, name.size() / 3));
    std::optional<std::string> best;
    size_t bestDistance = limit + 1;
    for (const std::string& candidate : candidates) {
        size_t distance = editDistance(name, candidate);
        if (distance < bestDistance) {
            bestDistance = distance;
            best = candidate;
        }
    }
    return best;
}

}  // namespace varc::variants
