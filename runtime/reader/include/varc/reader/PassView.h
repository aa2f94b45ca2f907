// SPDX-License-Identifier: Apache-2.0
// One pass of an open Pack: tags, render state, keyword table, declared sets, variant lookup.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "varc/core/Result.h"
#include "varc/pack/PackModel.h"
#include "varc/reader/VariantView.h"
#include "varc/variants/LightKeywords.h"
#include "varc/variants/VariantKey.h"
#include "varc/variants/VariantSelector.h"

namespace varc::reader {

namespace detail {
class PackImage;
}

// A cheap handle (pointer + indices); valid while its Pack lives. See Pack for the
// thread-safety and allocation contracts.
class PassView {
public:
    PassView(const detail::PackImage* image, uint32_t shader, uint32_t record)
        : mImage(image), mShader(shader), mRecord(record) {}

    uint32_t shaderIndex() const { return mShader; }
    std::string_view shaderName() const;  // the name of the shader this pass belongs to
    uint32_t index() const;  // the pass's position in its source shader
    std::string_view name() const;
    std::string_view lightMode() const;
    size_t tagCount() const;
    std::pair<std::string_view, std::string_view> tag(size_t i) const;  // i < tagCount()
    // The value of tag |key| (ASCII case-insensitive), "" when absent.
    std::string_view tagValue(std::string_view key) const;
    pack::PackRenderState renderState() const;

    size_t keywordCount() const;
    std::string_view keyword(size_t bit) const;  // bit < keywordCount(); sorted by name
    std::optional<size_t> keywordIndex(std::string_view name) const;  // binary search
    size_t setCount() const;
    pack::DeclaredSet set(size_t i) const;  // i < setCount(); allocates
    // The keywords of the pass's dynamic_branch sets, sorted, each once ("" left out). They
    // select no variant (keyOf and lookup ignore them, as any name outside the keyword table);
    // each is a uniform integer of the programs that the draw sets to 1 when it enables the
    // keyword, else 0 (docs/KEYWORDS.md §12). Empty for packs built before varc recorded them.
    // Allocates. Example: `#pragma dynamic_branch _ RED GREEN` -> {"GREEN", "RED"}.
    std::vector<std::string> dynamicKeywords() const;

    // The key of |keywords|; names the pass does not declare are ignored (Unity: requested ∩
    // declared). Allocation-free. Example: {"SHADOWS_SCREEN", "FOG_EXP"} on a pass declaring
    // only SHADOWS_SCREEN gives the key with that one bit.
    variants::VariantKey keyOf(std::span<const std::string_view> keywords) const;
    variants::VariantKey keyOf(const std::vector<std::string>& keywords) const;
    std::vector<std::string> keywordsOf(const variants::VariantKey& key) const;

    size_t variantCount() const;
    // The variant at |enumerationIndex| < variantCount() in Unity's enumeration order.
    VariantView variant(size_t enumerationIndex) const;

    // Finds the variant for |key| (bits beyond the keyword table are ignored) under |policy|:
    // an exact match by binary search in the sorted index (allocation-free, any policy), else
    // variants::selectVariant over the enumeration order: Closest picks the nearest, First the
    // first variant, Exact and Strict fail. Errors (NotFound) name the shader, pass and
    // requested keywords, and for Exact/Strict the nearest variants.
    Result<VariantView> lookup(const variants::VariantKey& key,
                               variants::SelectionPolicy policy) const;
    Result<VariantView> lookup(std::span<const std::string_view> keywords,
                               variants::SelectionPolicy policy) const;
    Result<VariantView> lookup(const std::vector<std::string>& keywords,
                               variants::SelectionPolicy policy) const;
    // The variant Unity's built-in pipeline uses to draw |light| in this pass: the light's
    // keywords (variants::lightKeywords for the pass's LightMode) added to |materialKey|.
    // InvalidInput when the LightMode is not ForwardBase, ForwardAdd, Deferred or "".
    Result<VariantView> lookup(const variants::LightDescription& light,
                               variants::SelectionPolicy policy,
                               const variants::VariantKey& materialKey = {}) const;

    // "shader 'Custom/Lit' pass 0 'FORWARD' (LightMode ForwardBase)", for messages.
    std::string describe() const;

private:
    friend class VariantView;
    uint32_t field(uint32_t field) const;
    uint32_t findSorted(const variants::VariantKey& masked) const;  // pack::kNone if absent
    Result<VariantView> lookupMiss(const variants::VariantKey& requested,
                                   variants::SelectionPolicy policy) const;

    const detail::PackImage* mImage;
    uint32_t mShader;
    uint32_t mRecord;  // index into the Passes table
};

}  // namespace varc::reader
