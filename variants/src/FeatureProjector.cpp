// SPDX-License-Identifier: Apache-2.0
// Projects a requested keyword list onto one pass's shader_feature sets (docs/KEYWORDS.md §11).
#include "FeatureProjector.h"

#include <algorithm>

#include "varc/core/Check.h"

namespace varc::variants {

FeatureProjector::FeatureProjector(const PassKeywords& keywords, const VariantSpace& space,
                                   const std::vector<size_t>& featureSets)
    : mKeywords(keywords),
      mSpace(space),
      mFeatureSets(featureSets),
      mSkipped(keywords.skipped.begin(), keywords.skipped.end()) {
    for (size_t set = 0; set < keywords.sets.size(); ++set) {
        for (const std::string& keyword : keywords.sets[set].keywords) {
            if (!keyword.empty()) mSetOf.emplace(keyword, set);
        }
    }
    for (size_t i = 0; i < featureSets.size(); ++i) {
        VARC_CHECK(!space.setOptions()[featureSets[i]].empty()) << "feature set without options";
        mPositionOf.emplace(featureSets[i], i);
    }
    for (const KeywordSetDecl& set : keywords.dynamicBranches) {
        for (const std::string& keyword : set.keywords) mDynamic.insert(keyword);
    }
}

// Sorting a request's keywords: a keyword no set declares is ignored (R = requested ∩
// declared; dynamic_branch keywords are listed apart, they never make variants). A skipped
// keyword is ignored too (INFERRED: skip_variants removes the keyword "as if never declared",
// so a material with it falls back to its set's remaining options instead of losing its whole
// combination). multi_compile keywords do not matter: every state ships.
RequestProjection FeatureProjector::project(const std::vector<std::string>& keywords) const {
    RequestProjection projection;
    std::vector<std::vector<std::string>> enabled(mFeatureSets.size());
    std::unordered_set<std::string> seen;
    for (const std::string& keyword : keywords) {
        if (keyword.empty() || !seen.insert(keyword).second) continue;
        auto declared = mSetOf.find(keyword);
        if (declared == mSetOf.end()) {
            (mDynamic.count(keyword) ? projection.dynamicBranch : projection.undeclared)
                .push_back(keyword);
        } else if (mSkipped.count(keyword) != 0) {
            projection.skipped.push_back(keyword);
        } else if (auto feature = mPositionOf.find(declared->second);
                   feature != mPositionOf.end()) {
            enabled[feature->second].push_back(keyword);
        } else {
            projection.multiCompile.push_back(keyword);
        }
    }
    for (size_t i = 0; i < mFeatureSets.size(); ++i) {
        const size_t option = pick(i, enabled[i], projection);
        projection.options.push_back(option);
        projection.key = projection.key | mSpace.setOptions()[mFeatureSets[i]][option];
    }
    return projection;
}

// One set's option (docs/KEYWORDS.md §11): the enabled keyword; with two or more, the first in
// declared order (UNVERIFIED; recorded as a conflict for a warning); with none, the `_` entry,
// else the first remaining keyword (UNVERIFIED, Unity's old "first one is used" rule; recorded
// in defaultedSets for a warning).
size_t FeatureProjector::pick(size_t position, const std::vector<std::string>& enabled,
                              RequestProjection& projection) const {
    const size_t set = mFeatureSets[position];
    const std::vector<VariantKey>& options = mSpace.setOptions()[set];
    if (enabled.empty()) {
        auto off = std::find(options.begin(), options.end(), VariantKey{});
        if (off != options.end()) return static_cast<size_t>(off - options.begin());
        projection.defaultedSets.push_back(set);
        return 0;
    }
    const std::vector<std::string>& declared = mKeywords.sets[set].keywords;
    auto kept =
        std::find_first_of(declared.begin(), declared.end(), enabled.begin(), enabled.end());
    VARC_CHECK(kept != declared.end()) << "enabled keyword outside its set";
    if (enabled.size() > 1) {
        FeatureConflict conflict{set, *kept, {}};
        for (const std::string& keyword : enabled) {
            if (keyword != *kept) conflict.dropped.push_back(keyword);
        }
        projection.conflicts.push_back(std::move(conflict));
    }
    const VariantKey key = mSpace.table().keyOf({*kept});
    return static_cast<size_t>(std::find(options.begin(), options.end(), key) - options.begin());
}

}  // namespace varc::variants
