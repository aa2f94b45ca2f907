// SPDX-License-Identifier: Apache-2.0
// MaterialSelection: distinct request projections pin the shader_feature sets of one pass.
#include "varc/variants/MaterialSelection.h"

#include <algorithm>
#include <map>
#include <optional>

#include "FeatureProjector.h"
#include "varc/core/Check.h"
#include "varc/core/SaturatingMath.h"
#include "varc/variants/KeywordList.h"

namespace varc::variants {

namespace {

bool hasMaterial(const std::vector<KeywordRequest>& requests) {
    return std::any_of(requests.begin(), requests.end(), [](const KeywordRequest& request) {
        return request.kind == RequestKind::Material;
    });
}

VariantVerdict verdict(bool ships, VerdictReason reason, std::string text) {
    return {ships, reason, {}, std::move(text)};
}

std::string describeRequest(const KeywordRequest& request) {
    const char* kind = request.kind == RequestKind::Material ? "material" : "collection variant";
    return std::string(kind) + " '" + request.name + "'";
}

}  // namespace

// The rules (docs/KEYWORDS.md §11):
//  * multi_compile sets (shortcuts included) ship every option; dynamic_branch makes none;
//  * shader_feature sets ship the union over requests of each request's whole combination,
//    never the product of per-set unions (FeatureProjector: undeclared keywords ignored);
//  * no Material request: the all-off combination ships (INFERRED, no primary source), as
//    well as any collection entries; collection entries project like materials and their
//    multi_compile keywords change nothing (inferred: a collection entry acts like a material);
//  * always included: every declared variant ships, shader_feature counted like multi_compile;
//  * skip_variants and the shortcut rules apply to every combination (they are in the space).
MaterialSelection MaterialSelection::select(const PassKeywords& keywords, const VariantSpace& space,
                                            std::vector<KeywordRequest> requests,
                                            bool alwaysIncluded) {
    VARC_CHECK(keywords.sets.size() == space.setOptions().size())
        << "MaterialSelection: keywords and space describe different passes";
    MaterialSelection selection(space);
    selection.mRequests = std::move(requests);
    selection.mAlwaysIncluded = alwaysIncluded;
    for (size_t set = 0; set < keywords.sets.size(); ++set) {
        if (keywords.sets[set].kind != DirectiveKind::ShaderFeature) continue;
        selection.mFeatureSets.push_back(set);
        if (space.setOptions()[set].empty()) selection.mEmpty = true;
    }
    selection.mPins.sets = selection.mFeatureSets;
    if (alwaysIncluded) selection.mSelected = space.count();
    if (selection.mEmpty) return selection;  // a fully skipped set: nothing ships
    FeatureProjector projector(keywords, selection.mSpace, selection.mFeatureSets);
    for (const KeywordRequest& request : selection.mRequests) {
        selection.mProjections.push_back(projector.project(request.keywords));
    }
    std::optional<std::vector<size_t>> allOff;
    if (!hasMaterial(selection.mRequests)) allOff = projector.project({}).options;
    selection.addCombinations(allOff);
    return selection;
}

// Distinct projections, sorted, each with the requests behind it; the pinned spaces they
// define are disjoint (two projections differ in some set's option), so counts add up.
void MaterialSelection::addCombinations(const std::optional<std::vector<size_t>>& allOff) {
    std::map<std::vector<size_t>, std::vector<size_t>> requestsOf;
    for (size_t i = 0; i < mRequests.size(); ++i) requestsOf[mProjections[i].options].push_back(i);
    if (allOff) requestsOf.try_emplace(*allOff);
    mDefaultAdded = allOff.has_value();
    for (auto& [options, requests] : requestsOf) {
        mPins.combinations.push_back(options);
        mRequestsOf.push_back(std::move(requests));
        if (mAlwaysIncluded) continue;  // counted as the whole space
        mSelected = saturatingAdd(mSelected, mSpace.countPinned(mPins.sets, options));
    }
}

SelectionCounts MaterialSelection::counts() const {
    return {mSpace.fullCount(), mSpace.count(), count()};
}

void MaterialSelection::forEach(const std::function<bool(const VariantKey&)>& visit) const {
    if (mAlwaysIncluded) return mSpace.forEach(visit);
    mSpace.forEachPinned(mPins, visit);
}

std::vector<VariantKey> MaterialSelection::enumerate() const {
    std::vector<VariantKey> keys;
    keys.reserve(static_cast<size_t>(std::min<uint64_t>(count(), uint64_t{1} << 20)));
    forEach([&keys](const VariantKey& key) {
        keys.push_back(key);
        return true;
    });
    return keys;
}

VariantVerdict MaterialSelection::explain(const VariantKey& key) const {
    std::optional<std::vector<size_t>> options = mSpace.optionsOf(key);
    if (!options) {
        return verdict(false, VerdictReason::NotDeclared,
                       "not a variant of this pass: its keywords are not one option of every set");
    }
    if (!mSpace.contains(key)) {
        return verdict(false, VerdictReason::NotDeclared, "a shortcut's validity rule excludes it");
    }
    if (mAlwaysIncluded) {
        return verdict(true, VerdictReason::AlwaysIncluded,
                       "the shader is always included: every declared variant ships");
    }
    std::vector<size_t> feature;
    for (size_t set : mFeatureSets) feature.push_back((*options)[set]);
    const auto& combinations = mPins.combinations;
    auto found = std::lower_bound(combinations.begin(), combinations.end(), feature);
    if (found == combinations.end() || *found != feature) {
        return verdict(false, VerdictReason::NotRequested, missingFeatureText(feature));
    }
    const std::vector<size_t>& requests = mRequestsOf[found - combinations.begin()];
    if (requests.empty()) {
        return verdict(true, VerdictReason::NoMaterialDefault,
                       "no material uses the shader: its all-off shader_feature combination ships");
    }
    std::string text = "enabled by ";
    for (size_t i = 0; i < requests.size(); ++i) {
        text += (i == 0 ? "" : ", ") + describeRequest(mRequests[requests[i]]);
    }
    return {true, VerdictReason::Requested, requests, text};
}

// Names the first shader_feature set whose option no request picks, e.g. "no material
// enables _DETAIL"; when every option is picked by someone, the combination is the gap.
std::string MaterialSelection::missingFeatureText(const std::vector<size_t>& options) const {
    if (mDefaultAdded && mPins.combinations.size() == 1 && mRequests.empty()) {
        return "no material uses the shader: only its all-off shader_feature combination ships";
    }
    const bool collections = std::any_of(mRequests.begin(), mRequests.end(), [](const auto& r) {
        return r.kind == RequestKind::CollectionVariant;
    });
    const std::string noun = collections ? "material or collection variant" : "material";
    const auto& combinations = mPins.combinations;
    VariantKey on;
    for (size_t i = 0; i < options.size(); ++i) {
        const std::vector<VariantKey>& setOptions = mSpace.setOptions()[mFeatureSets[i]];
        on = on | setOptions[options[i]];
        bool picked = std::any_of(combinations.begin(), combinations.end(),
                                  [&](const auto& c) { return c[i] == options[i]; });
        if (picked) continue;
        if (!setOptions[options[i]].empty()) {
            return "no " + noun + " enables " +
                   joinKeywords(mSpace.table().namesOf(setOptions[options[i]]));
        }
        VariantKey all;
        for (const VariantKey& option : setOptions) all = all | option;
        return "every " + noun + " enables one of " + joinKeywords(mSpace.table().namesOf(all));
    }
    return "no single " + noun + " has this shader_feature combination (" +
           joinKeywords(mSpace.table().namesOf(on)) + ")";
}

}  // namespace varc::variants
