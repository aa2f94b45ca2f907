// SPDX-License-Identifier: Apache-2.0
// Block-wide keyword rules: dynamic_branch precedence, repeated sets, keywords in two sets.
#include "pragma/DeclarationChecker.h"

#include <algorithm>
#include <cstddef>
#include <map>
#include <string>

namespace varc::variants {

namespace {

std::string position(const SourceLocation& location) {
    std::string text = "line " + std::to_string(location.line);
    if (location.column != 0) text += ", column " + std::to_string(location.column);
    return text;
}

std::vector<std::string> sortedKeywords(const KeywordSetDecl& decl) {
    std::vector<std::string> keywords = decl.keywords;
    std::sort(keywords.begin(), keywords.end());
    return keywords;
}

std::string displaySet(const KeywordSetDecl& decl) {
    std::string text = decl.directive;
    for (const std::string& keyword : decl.keywords)
        text += " " + (keyword.empty() ? "_" : keyword);
    return text;
}

bool hasKeyword(const KeywordSetDecl& decl) {
    return std::any_of(decl.keywords.begin(), decl.keywords.end(),
                       [](const std::string& keyword) { return !keyword.empty(); });
}

}  // namespace

void DeclarationChecker::resolveDynamicBranches(std::vector<DeclaredSet>& sets,
                                                const std::vector<DeclaredSet>& branches) {
    std::map<std::string, SourceLocation> dynamic;
    for (const DeclaredSet& branch : branches) {
        for (size_t i = 0; i < branch.decl.keywords.size(); ++i) {
            const std::string& keyword = branch.decl.keywords[i];
            if (!keyword.empty()) dynamic.emplace(keyword, branch.keywordLocations[i]);
        }
    }
    for (DeclaredSet& set : sets) {
        for (size_t i = set.decl.keywords.size(); i-- > 0;) {
            auto it = dynamic.find(set.decl.keywords[i]);
            if (it == dynamic.end()) continue;
            mSink.report({Severity::Warning,
                          set.keywordLocations[i],
                          "keyword '" + it->first + "' is also declared by dynamic_branch, " +
                              "which wins: it produces no variants",
                          {{it->second, "declared by dynamic_branch here"}}});
            set.decl.keywords.erase(set.decl.keywords.begin() + static_cast<std::ptrdiff_t>(i));
            set.keywordLocations.erase(set.keywordLocations.begin() +
                                       static_cast<std::ptrdiff_t>(i));
        }
    }
    std::erase_if(sets, [](const DeclaredSet& set) { return !hasKeyword(set.decl); });
}

// Unity accepts a set written again exactly (same keywords in any order, same directive kind
// and scope), e.g. `multi_compile _ VERTEXLIGHT_ON` beside `multi_compile_fwdbase`, which
// declares that set itself: the variant count does not change. varc merges it with a note.
// A stage suffix does not make the set another one (`multi_compile_domain _ VERTEXLIGHT_ON`):
// Unity ignores stage suffixes on Vulkan, so the merged set is defined in the stages of both.
void DeclarationChecker::mergeIdenticalSets(std::vector<DeclaredSet>& sets) {
    for (size_t i = sets.size(); i-- > 1;) {
        const KeywordSetDecl& later = sets[i].decl;
        std::vector<std::string> mine = sortedKeywords(later);
        for (size_t j = 0; j < i; ++j) {
            const KeywordSetDecl& first = sets[j].decl;
            if (first.kind != later.kind || first.local != later.local ||
                sortedKeywords(first) != mine)
                continue;
            sets[j].decl.stages = sets[j].decl.stages | later.stages;
            mSink.report({Severity::Note,
                          sets[i].directiveLocation,
                          "keyword set '" + displaySet(later) + "' is the same as '" +
                              displaySet(first) + "' at " + position(sets[j].directiveLocation) +
                              "; merged, as Unity does",
                          {{sets[j].directiveLocation, "first declared here"}}});
            sets.erase(sets.begin() + static_cast<std::ptrdiff_t>(i));
            break;
        }
    }
}

bool DeclarationChecker::checkUnique(const std::vector<DeclaredSet>& sets) {
    std::vector<bool> repeated(sets.size(), false);
    bool ok = true;
    for (size_t i = 0; i < sets.size(); ++i) {
        repeated[i] = isRepeatedSet(sets, i);
        ok = ok && !repeated[i];
    }
    return checkKeywordsUnique(sets, repeated) && ok;
}

// Same keywords in any order is a repeat: `multi_compile A B` then `multi_compile B A`.
bool DeclarationChecker::isRepeatedSet(const std::vector<DeclaredSet>& sets, size_t index) {
    std::vector<std::string> mine = sortedKeywords(sets[index].decl);
    for (size_t j = 0; j < index; ++j) {
        if (sortedKeywords(sets[j].decl) != mine) continue;
        const SourceLocation& first = sets[j].directiveLocation;
        mSink.report({Severity::Error,
                      sets[index].directiveLocation,
                      "duplicate keyword set '" + displaySet(sets[index].decl) +
                          "'; the same set was first declared at " + position(first),
                      {{first, "first declared here"}}});
        return true;
    }
    return false;
}

// A keyword in two sets would give two meanings to one VariantKey bit.
bool DeclarationChecker::checkKeywordsUnique(const std::vector<DeclaredSet>& sets,
                                             const std::vector<bool>& repeated) {
    std::map<std::string, SourceLocation> firstSeen;
    bool ok = true;
    for (size_t s = 0; s < sets.size(); ++s) {
        if (repeated[s]) continue;
        const KeywordSetDecl& decl = sets[s].decl;
        for (size_t i = 0; i < decl.keywords.size(); ++i) {
            if (decl.keywords[i].empty()) continue;
            auto [it, inserted] = firstSeen.emplace(decl.keywords[i], sets[s].keywordLocations[i]);
            if (inserted) continue;
            mSink.report({Severity::Error,
                          sets[s].keywordLocations[i],
                          "keyword '" + decl.keywords[i] + "' is already declared by another " +
                              "set, first at " + position(it->second),
                          {{it->second, "first declared here"}}});
            ok = false;
        }
    }
    return ok;
}

}  // namespace varc::variants
