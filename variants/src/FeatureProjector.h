// SPDX-License-Identifier: Apache-2.0
// Projects a requested keyword list onto one pass's shader_feature sets (Unity's R ∩ declared).
#pragma once

#include <cstddef>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "varc/variants/MaterialSelection.h"

namespace varc::variants {

// Built once per pass; project() is then O(keywords + shader_feature options).
class FeatureProjector {
public:
    // |featureSets|: the shader_feature sets of |keywords|, ascending; |space| is built from
    // |keywords|. All three must outlive the projector. Every feature set must keep an option.
    FeatureProjector(const PassKeywords& keywords, const VariantSpace& space,
                     const std::vector<size_t>& featureSets);

    // The option |keywords| picks in every shader_feature set, and what it ignored (rules in
    // FeatureProjector.cpp). project({}) is the all-off combination.
    RequestProjection project(const std::vector<std::string>& keywords) const;

private:
    size_t pick(size_t position, const std::vector<std::string>& enabled,
                RequestProjection& projection) const;

    const PassKeywords& mKeywords;
    const VariantSpace& mSpace;
    const std::vector<size_t>& mFeatureSets;
    std::unordered_map<std::string, size_t> mSetOf;  // declared keyword -> its set
    std::unordered_map<size_t, size_t> mPositionOf;  // feature set -> index in mFeatureSets
    std::unordered_set<std::string> mSkipped;
    std::unordered_set<std::string> mDynamic;
};

}  // namespace varc::variants
