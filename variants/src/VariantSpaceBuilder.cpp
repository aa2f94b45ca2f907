// SPDX-License-Identifier: Apache-2.0
// Builds a VariantSpace from PassKeywords: keyword table, per-set options, compiled rules.
#include "VariantSpaceBuilder.h"

#include <algorithm>
#include <numeric>
#include <set>
#include <string>

#include "varc/core/SaturatingMath.h"

namespace varc::variants {

namespace {

size_t findRoot(std::vector<size_t>& parent, size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
}

// The declared, non-skipped keywords sorted by name; nullopt (after an error at the set that
// brings in keyword kMaxKeywords + 1) when there are too many for a VariantKey.
std::optional<std::vector<std::string>> collectNames(const PassKeywords& keywords,
                                                     DiagnosticSink& sink) {
    std::set<std::string> skipped(keywords.skipped.begin(), keywords.skipped.end());
    std::set<std::string> names;
    for (const KeywordSetDecl& set : keywords.sets) {
        for (const std::string& keyword : set.keywords) {
            if (keyword.empty() || skipped.count(keyword) != 0) continue;
            names.insert(keyword);
            if (names.size() > VariantKey::kMaxKeywords) {
                sink.error(set.location, "the pass declares more than " +
                                             std::to_string(VariantKey::kMaxKeywords) +
                                             " keywords; '" + keyword + "' is one too many");
                return std::nullopt;
            }
        }
    }
    return std::vector<std::string>(names.begin(), names.end());
}

}  // namespace

std::optional<VariantSpace> VariantSpaceBuilder::build(const PassKeywords& keywords,
                                                       DiagnosticSink& sink) {
    std::optional<std::vector<std::string>> names = collectNames(keywords, sink);
    if (!names) return std::nullopt;
    VariantSpace space{KeywordTable(std::move(*names))};
    addSetOptions(space, keywords);
    addRules(space, keywords);
    return space;
}

void VariantSpaceBuilder::addSetOptions(VariantSpace& space, const PassKeywords& keywords) {
    const KeywordTable& table = space.mTable;
    std::set<std::string> skipped(keywords.skipped.begin(), keywords.skipped.end());
    for (const KeywordSetDecl& set : keywords.sets) {
        std::vector<VariantKey> options;
        for (const std::string& keyword : set.keywords) {
            if (skipped.count(keyword) != 0) continue;
            options.push_back(keyword.empty() ? VariantKey{} : table.keyOf({keyword}));
        }
        space.mAllSets.push_back(space.mSetOptions.size());
        space.mSetOptions.push_back(std::move(options));
        space.mFullCount = saturatingMultiply(space.mFullCount, set.keywords.size());
    }
}

// Rules over undeclared keywords are dropped (they can never fire); the sets a rule mentions
// are linked, so count() enumerates them jointly.
void VariantSpaceBuilder::addRules(VariantSpace& space, const PassKeywords& keywords) {
    const KeywordTable& table = space.mTable;
    std::vector<size_t> setOfBit(table.size());
    for (size_t s = 0; s < space.mSetOptions.size(); ++s) {
        for (const VariantKey& option : space.mSetOptions[s]) {
            for (size_t bit = 0; bit < table.size(); ++bit) {
                if (option.test(bit)) setOfBit[bit] = s;
            }
        }
    }
    std::vector<size_t> parent(space.mSetOptions.size());
    std::iota(parent.begin(), parent.end(), size_t{0});
    space.mRulesAtSet.assign(space.mSetOptions.size(), {});
    for (const ValidityRule& rule : keywords.rules) {
        std::optional<size_t> bit = table.indexOf(rule.keyword);
        if (!bit) continue;
        VariantSpace::Rule compiled;
        compiled.keyword.set(*bit);
        compiled.requiresAnyOf = table.keyOf(rule.requiresAnyOf);
        compiled.forbids = table.keyOf(rule.forbids);
        compiled.hasRequirement = !rule.requiresAnyOf.empty();
        VariantKey mentioned = compiled.keyword | compiled.requiresAnyOf | compiled.forbids;
        size_t home = findRoot(parent, setOfBit[*bit]);
        compiled.lastSet = setOfBit[*bit];
        for (size_t other = 0; other < table.size(); ++other) {
            if (!mentioned.test(other)) continue;
            parent[findRoot(parent, setOfBit[other])] = home;
            compiled.lastSet = std::max(compiled.lastSet, setOfBit[other]);
        }
        space.mRulesAtSet[compiled.lastSet].push_back(space.mRules.size());
        space.mRules.push_back(compiled);
    }
    groupSets(space, std::move(parent));
}

void VariantSpaceBuilder::groupSets(VariantSpace& space, std::vector<size_t> parent) {
    std::vector<bool> ruled(parent.size(), false);
    for (const VariantSpace::Rule& rule : space.mRules) ruled[rule.lastSet] = true;
    std::vector<std::vector<size_t>> members(parent.size());
    for (size_t s = 0; s < parent.size(); ++s) members[findRoot(parent, s)].push_back(s);
    for (size_t root = 0; root < parent.size(); ++root) {
        const std::vector<size_t>& group = members[root];
        bool linked = std::any_of(group.begin(), group.end(), [&](size_t s) { return ruled[s]; });
        if (group.empty()) continue;
        if (linked) {
            space.mLinkedGroups.push_back(group);
        } else {
            space.mFreeSets.insert(space.mFreeSets.end(), group.begin(), group.end());
        }
    }
    std::sort(space.mFreeSets.begin(), space.mFreeSets.end());
}

}  // namespace varc::variants
