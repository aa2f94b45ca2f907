// SPDX-License-Identifier: Apache-2.0
// Strip rules: which passes they apply to, and what they remove from a pass's variants.
#include "varc/variants/StripRules.h"

#include <algorithm>
#include <cctype>

namespace varc::variants {

namespace {

bool equalIgnoringCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() &&
           std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

// The keywords |stage| sees: those of sets without a suffix or suffixed with that stage.
bool seenByStage(const PassKeywords& keywords, const std::string& keyword,
                 std::optional<Stage> stage) {
    if (!stage) return true;
    for (const KeywordSetDecl& set : keywords.sets) {
        if (!hasStage(set.stages, *stage)) continue;
        if (std::find(set.keywords.begin(), set.keywords.end(), keyword) != set.keywords.end()) {
            return true;
        }
    }
    return false;
}

}  // namespace

bool globMatches(std::string_view pattern, std::string_view text) {
    // Iterative matching with one backtrack point: linear in practice, never exponential.
    size_t p = 0, t = 0, star = std::string_view::npos, resume = 0;
    while (t < text.size()) {
        if (p < pattern.size() && pattern[p] == '*') {
            star = p++;
            resume = t;
        } else if (p < pattern.size() && pattern[p] == text[t]) {
            ++p;
            ++t;
        } else if (star != std::string_view::npos) {
            p = star + 1;
            t = ++resume;
        } else {
            return false;
        }
    }
    while (p < pattern.size() && pattern[p] == '*') ++p;
    return p == pattern.size();
}

bool stripRuleApplies(const StripRule& rule, std::string_view shaderName,
                      std::string_view passName, std::string_view lightMode) {
    if (!rule.shader.empty() && !globMatches(rule.shader, shaderName)) return false;
    return rule.pass.empty() || equalIgnoringCase(rule.pass, passName) ||
           equalIgnoringCase(rule.pass, lightMode);
}

PassStripRule compileStripRule(const StripRule& rule, const PassKeywords& keywords,
                               const KeywordTable& table) {
    PassStripRule compiled;
    for (const std::string& keyword : rule.with) {
        std::optional<size_t> bit = table.indexOf(keyword);
        if (!bit || !seenByStage(keywords, keyword, rule.stage)) {
            compiled.never = true;
        } else {
            compiled.with.set(*bit);
        }
    }
    // An undeclared |without| keyword is always off: the condition holds, no bit needed.
    for (const std::string& keyword : rule.without) {
        std::optional<size_t> bit = table.indexOf(keyword);
        if (bit && seenByStage(keywords, keyword, rule.stage)) compiled.without.set(*bit);
    }
    return compiled;
}

std::vector<uint64_t> applyStripRules(const std::vector<PassStripRule>& rules,
                                      std::vector<VariantKey>& keys) {
    std::vector<uint64_t> removed(rules.size(), 0);
    auto matches = [](const PassStripRule& rule, const VariantKey& key) {
        return !rule.never && (key & rule.with) == rule.with && (key & rule.without).empty();
    };
    auto end = std::remove_if(keys.begin(), keys.end(), [&](const VariantKey& key) {
        for (size_t r = 0; r < rules.size(); ++r) {
            if (matches(rules[r], key)) {
                ++removed[r];
                return true;
            }
        }
        return false;
    });
    keys.erase(end, keys.end());
    return removed;
}

}  // namespace varc::variants
