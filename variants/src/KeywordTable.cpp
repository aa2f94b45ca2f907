// SPDX-License-Identifier: Apache-2.0
// KeywordTable: a pass's sorted keyword names and their VariantKey bits.
#include <algorithm>

#include "varc/core/Check.h"
#include "varc/variants/VariantSpace.h"

namespace varc::variants {

KeywordTable::KeywordTable(std::vector<std::string> sortedUniqueNames)
    : mNames(std::move(sortedUniqueNames)) {
    VARC_CHECK(mNames.size() <= VariantKey::kMaxKeywords)
        << "KeywordTable with " << mNames.size() << " keywords";
    VARC_CHECK(std::adjacent_find(mNames.begin(), mNames.end(), std::greater_equal<>()) ==
               mNames.end())
        << "KeywordTable names must be sorted and unique";
}

std::optional<size_t> KeywordTable::indexOf(std::string_view name) const {
    auto it = std::lower_bound(mNames.begin(), mNames.end(), name,
                               [](const std::string& a, std::string_view b) { return a < b; });
    if (it == mNames.end() || *it != name) return std::nullopt;
    return static_cast<size_t>(it - mNames.begin());
}

VariantKey KeywordTable::keyOf(const std::vector<std::string>& names) const {
    VariantKey key;
    for (const std::string& keyword : names) {
        if (std::optional<size_t> bit = indexOf(keyword)) key.set(*bit);
    }
    return key;
}

std::vector<std::string> KeywordTable::namesOf(const VariantKey& key) const {
    std::vector<std::string> result;
    for (size_t bit = 0; bit < mNames.size(); ++bit) {
        if (key.test(bit)) result.push_back(mNames[bit]);
    }
    return result;
}

std::string KeywordTable::bitLayoutTable() const {
    size_t width = std::string_view("keyword").size();
    for (const std::string& keyword : mNames) width = std::max(width, keyword.size());
    const std::string rule = "+-----+" + std::string(width + 2, '-') + "+\n";
    auto row = [&](std::string bit, const std::string& keyword) {
        bit.insert(0, 3 - std::min<size_t>(3, bit.size()), ' ');
        return "| " + bit + " | " + keyword + std::string(width - keyword.size(), ' ') + " |\n";
    };
    std::string text = rule + row("bit", "keyword") + rule;
    for (size_t bit = 0; bit < mNames.size(); ++bit) text += row(std::to_string(bit), mNames[bit]);
    if (!mNames.empty()) text += rule;
    return text;
}

}  // namespace varc::variants
