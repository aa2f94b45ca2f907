// SPDX-License-Identifier: Apache-2.0
// Which variants of one pass a Unity player build compiles, from the materials that use it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "varc/variants/PassKeywords.h"
#include "varc/variants/VariantKey.h"
#include "varc/variants/VariantSpace.h"

namespace varc::variants {

// Where a requested keyword list comes from. Both project the same way; they differ only in
// the "no material" rule (the all-off combination ships when no Material request exists).
enum class RequestKind { Material, CollectionVariant };

// One requested keyword list: a material's enabled keywords, or one ShaderVariantCollection
// entry. The caller passes a collection entry only to the passes whose PassType matches it.
struct KeywordRequest {
    RequestKind kind = RequestKind::Material;
    std::string name;                   // the caller's label, for reasons ("Rock.mat")
    std::vector<std::string> keywords;  // any order; duplicates and "" are harmless
};

// A shader_feature set where the request enabled two or more keywords: |kept| is the first in
// declared order (a rule Unity does not document; docs/KEYWORDS.md §11), |dropped| the others.
struct FeatureConflict {
    size_t set = 0;  // index into PassKeywords::sets
    std::string kept;
    std::vector<std::string> dropped;
};

// How one request maps onto the pass: the option it picks in every shader_feature set and what
// it ignored (for warnings). Keyword lists keep the request's order.
struct RequestProjection {
    std::vector<size_t> options;             // per featureSets() entry: index into setOptions()
    VariantKey key;                          // the shader_feature keywords the options turn on
    std::vector<std::string> undeclared;     // no set of the pass declares them: ignored
    std::vector<std::string> skipped;        // removed by skip_variants: ignored as undeclared
    std::vector<std::string> dynamicBranch;  // dynamic_branch keywords: no variants
    std::vector<std::string> multiCompile;   // every state ships anyway: no effect
    std::vector<FeatureConflict> conflicts;  // 2+ keywords of one set on
    std::vector<size_t> defaultedSets;       // `_`-less sets with none on: first keyword assumed
};

// Counts per stage of Unity's build log (docs/PROJECTS.md). More stages (settings, user rules) come later.
struct SelectionCounts {
    uint64_t full = 0;      // product of the set sizes ("Full variant space")
    uint64_t declared = 0;  // after skip_variants and the shortcuts' validity rules
    uint64_t selected = 0;  // after materials and collections
};

// Why explain() says a variant ships or not.
enum class VerdictReason {
    AlwaysIncluded,     // ships: every declared variant of an always-included shader ships
    Requested,          // ships: |requests| project onto its shader_feature options
    NoMaterialDefault,  // ships: no material uses the shader, the all-off combination (INFERRED)
    NotDeclared,        // no: not a variant of the pass (undeclared, skipped or invalid keys)
    NotRequested,       // no: no request projects onto its shader_feature options
};

struct VariantVerdict {
    bool ships = false;
    VerdictReason reason = VerdictReason::NotDeclared;
    std::vector<size_t> requests;  // indices into the requests, ascending (Requested)
    std::string text;              // one sentence, e.g. "no material enables _DETAIL"
};

// The shipped variants of one pass: each distinct request projection pins the shader_feature
// sets, and the pass ships the disjoint union over projections of the pinned space. Counting
// and explaining never enumerate; forEach visits only shipped variants. Rules: reference
// docs/KEYWORDS.md §11 and docs/PROJECTS.md, choices in MaterialSelection.cpp.
class MaterialSelection {
public:
    // |keywords| and |space| describe the same pass (space = VariantSpace::build(keywords)).
    // |alwaysIncluded|: every declared variant ships (GraphicsSettings' Always Included list).
    static MaterialSelection select(const PassKeywords& keywords, const VariantSpace& space,
                                    std::vector<KeywordRequest> requests, bool alwaysIncluded);

    SelectionCounts counts() const;
    uint64_t count() const { return mSelected; }  // saturates at UINT64_MAX
    // Shipped variants in VariantSpace order (first declared set slowest), whatever the order
    // of the requests; stop early by returning false.
    void forEach(const std::function<bool(const VariantKey&)>& visit) const;
    std::vector<VariantKey> enumerate() const;  // use count() first; this allocates

    // Whether |key| (in space().table()'s layout) ships, and why. O(requests + sets x options).
    VariantVerdict explain(const VariantKey& key) const;

    const VariantSpace& space() const { return mSpace; }
    const std::vector<size_t>& featureSets() const { return mFeatureSets; }  // ascending
    const std::vector<KeywordRequest>& requests() const { return mRequests; }
    // One per request, same order; empty when a shader_feature set has every keyword skipped.
    const std::vector<RequestProjection>& projections() const { return mProjections; }
    // The distinct requested shader_feature combinations, sorted, plus the all-off one when no
    // material exists; one option index per featureSets() entry. A combination whose every
    // variant breaks a shortcut rule is listed but ships nothing. Also filled when always
    // included (explain ignores it then).
    const std::vector<std::vector<size_t>>& combinations() const { return mPins.combinations; }

private:
    explicit MaterialSelection(VariantSpace space) : mSpace(std::move(space)) {}
    void addCombinations(const std::optional<std::vector<size_t>>& allOff);
    std::string missingFeatureText(const std::vector<size_t>& options) const;

    VariantSpace mSpace;
    std::vector<size_t> mFeatureSets;
    std::vector<KeywordRequest> mRequests;
    std::vector<RequestProjection> mProjections;
    VariantSpace::Pins mPins;                      // sets = mFeatureSets
    std::vector<std::vector<size_t>> mRequestsOf;  // per combination: requests, ascending
    bool mAlwaysIncluded = false;
    bool mDefaultAdded = false;  // the no-material combination is in mPins
    bool mEmpty = false;         // a shader_feature set has no option left
    uint64_t mSelected = 0;
};

}  // namespace varc::variants
