// SPDX-License-Identifier: Apache-2.0
// One pass of an open Pack: tags, render state, keyword table and declared sets.
#include "varc/reader/PassView.h"

#include <algorithm>

#include "PackImage.h"
#include "varc/core/AsciiCase.h"
#include "varc/core/Check.h"
#include "varc/pack/PackTables.h"

namespace varc::reader {

using pack::Chunk;

uint32_t PassView::field(uint32_t field) const {
    return mImage->get(Chunk::Passes, mRecord, field);
}

uint32_t PassView::index() const { return field(pack::kPassIndex); }
std::string_view PassView::shaderName() const {
    return mImage->string(mImage->get(Chunk::Shaders, mShader, pack::kShaderName));
}
std::string_view PassView::name() const { return mImage->string(field(pack::kPassName)); }
std::string_view PassView::lightMode() const { return mImage->string(field(pack::kPassLightMode)); }

size_t PassView::tagCount() const { return field(pack::kPassTagCount); }

std::pair<std::string_view, std::string_view> PassView::tag(size_t i) const {
    VARC_CHECK(i < tagCount()) << "tag " << i << " of " << tagCount();
    uint32_t record = field(pack::kPassTagFirst) + static_cast<uint32_t>(i);
    return {mImage->string(mImage->get(Chunk::Tags, record, pack::kTagKey)),
            mImage->string(mImage->get(Chunk::Tags, record, pack::kTagValue))};
}

std::string_view PassView::tagValue(std::string_view key) const {
    for (size_t i = 0; i < tagCount(); ++i) {
        auto [name, value] = tag(i);
        if (equalsIgnoreAsciiCase(name, key)) return value;
    }
    return {};
}

pack::PackRenderState PassView::renderState() const {
    uint32_t record = field(pack::kPassRenderState);
    auto get = [&](uint32_t f) { return mImage->get(Chunk::RenderStates, record, f); };
    pack::PackRenderState state;
    state.blendEnabled = get(pack::kRsBlendEnabled) != 0;
    state.stencilEnabled = get(pack::kRsStencilEnabled) != 0;
    pack::forEachStateField(state, [&](uint32_t slot, auto& stateField) {
        using T = decltype(stateField.value);
        stateField.value = pack::stateValueFromBits<T>(get(pack::renderStateValueField(slot)));
        stateField.property = mImage->string(get(pack::renderStatePropertyField(slot)));
    });
    return state;
}

size_t PassView::keywordCount() const { return field(pack::kPassKeywordCount); }

std::string_view PassView::keyword(size_t bit) const {
    VARC_CHECK(bit < keywordCount()) << "keyword " << bit << " of " << keywordCount();
    return mImage->listString(field(pack::kPassKeywordFirst) + static_cast<uint32_t>(bit));
}

std::optional<size_t> PassView::keywordIndex(std::string_view name) const {
    size_t low = 0, high = keywordCount();
    while (low < high) {
        size_t middle = low + (high - low) / 2;
        std::string_view candidate = keyword(middle);
        if (candidate == name) return middle;
        if (candidate < name) {
            low = middle + 1;
        } else {
            high = middle;
        }
    }
    return std::nullopt;
}

size_t PassView::setCount() const { return field(pack::kPassSetCount); }

pack::DeclaredSet PassView::set(size_t i) const {
    VARC_CHECK(i < setCount()) << "set " << i << " of " << setCount();
    uint32_t record = field(pack::kPassSetFirst) + static_cast<uint32_t>(i);
    pack::DeclaredSet set;
    set.directive = mImage->string(mImage->get(Chunk::KeywordSets, record, pack::kSetDirective));
    uint32_t first = mImage->get(Chunk::KeywordSets, record, pack::kSetKeywordFirst);
    uint32_t count = mImage->get(Chunk::KeywordSets, record, pack::kSetKeywordCount);
    for (uint32_t k = 0; k < count; ++k) set.keywords.emplace_back(mImage->listString(first + k));
    return set;
}

std::vector<std::string> PassView::dynamicKeywords() const {
    std::vector<std::string> names;
    for (size_t i = 0; i < setCount(); ++i) {
        pack::DeclaredSet declared = set(i);
        if (!pack::isDynamicBranchDirective(declared.directive)) continue;
        for (std::string& keyword : declared.keywords) {
            if (!keyword.empty()) names.push_back(std::move(keyword));
        }
    }
    std::sort(names.begin(), names.end());
    names.erase(std::unique(names.begin(), names.end()), names.end());
    return names;
}

namespace {

// Sets the bit of |name| in |key| when |pass| declares it.
void addKeyword(const PassView& pass, std::string_view name, variants::VariantKey& key) {
    if (std::optional<size_t> bit = pass.keywordIndex(name)) {
        key.words()[*bit / 64] |= uint64_t{1} << (*bit % 64);
    }
}

}  // namespace

variants::VariantKey PassView::keyOf(std::span<const std::string_view> keywords) const {
    variants::VariantKey key;
    for (std::string_view name : keywords) addKeyword(*this, name, key);
    return key;
}

variants::VariantKey PassView::keyOf(const std::vector<std::string>& keywords) const {
    variants::VariantKey key;
    for (const std::string& name : keywords) addKeyword(*this, name, key);
    return key;
}

std::vector<std::string> PassView::keywordsOf(const variants::VariantKey& key) const {
    std::vector<std::string> names;
    for (size_t bit = 0; bit < keywordCount(); ++bit) {
        if ((key.words()[bit / 64] >> (bit % 64)) & 1) names.emplace_back(keyword(bit));
    }
    return names;
}

size_t PassView::variantCount() const { return field(pack::kPassVariantCount); }

VariantView PassView::variant(size_t enumerationIndex) const {
    VARC_CHECK(enumerationIndex < variantCount())
        << "variant " << enumerationIndex << " of " << variantCount();
    uint32_t record = field(pack::kPassVariantFirst) + static_cast<uint32_t>(enumerationIndex);
    uint32_t sorted = mImage->get(Chunk::VariantOrder, record, pack::kOrderPosition);
    return VariantView(mImage, mShader, mRecord, sorted, true);
}

std::string PassView::describe() const {
    std::string text = "shader '" + std::string(shaderName()) + "' pass " + std::to_string(index());
    if (!name().empty()) text += " '" + std::string(name()) + "'";
    if (!lightMode().empty()) text += " (LightMode " + std::string(lightMode()) + ")";
    return text;
}

}  // namespace varc::reader
