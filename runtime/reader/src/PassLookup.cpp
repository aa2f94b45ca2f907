// SPDX-License-Identifier: Apache-2.0
// Variant lookup in a pass: binary search of the sorted key index, selection policies on miss.
#include <array>

#include "PackImage.h"
#include "varc/pack/KeyEncoding.h"
#include "varc/pack/PackTables.h"
#include "varc/reader/PassView.h"

namespace varc::reader {

using pack::Chunk;

namespace {

// Position of |want| among |count| sorted one-word keys at |keys|, or kNone. Branch-free
// lower bound: the loop narrows [base, base + n) to the last key <= |want| with conditional
// moves, so its cost does not depend on mispredicted comparisons.
uint32_t findOneWord(const std::byte* keys, uint32_t count, uint64_t want) {
    if (count == 0) return pack::kNone;
    const std::byte* base = keys;
    for (uint32_t n = count; n > 1;) {
        uint32_t half = n / 2;
        base = pack::loadU64(base + 8 * size_t{half}) <= want ? base + 8 * size_t{half} : base;
        n -= half;
    }
    if (pack::loadU64(base) != want) return pack::kNone;
    return static_cast<uint32_t>((base - keys) / 8);
}

// The same for keys of |words| words (passes with more than 64 keywords).
uint32_t findWords(const std::byte* keys, uint32_t count, uint32_t words, const uint64_t* want) {
    auto compareAt = [&](uint32_t position) {
        std::array<uint64_t, pack::kMaxKeyWords> key{};
        for (uint32_t w = 0; w < words; ++w) {
            key[w] = pack::loadU64(keys + 8 * (size_t{position} * words + w));
        }
        return pack::compareKeyWords(key.data(), want, words);
    };
    uint32_t low = 0, high = count;
    while (low < high) {
        uint32_t middle = low + (high - low) / 2;
        int order = compareAt(middle);
        if (order == 0) return middle;
        if (order < 0) {
            low = middle + 1;
        } else {
            high = middle;
        }
    }
    return pack::kNone;
}

std::string braced(const std::vector<std::string>& names) {
    std::string text = "{";
    for (size_t i = 0; i < names.size(); ++i) text += (i ? " " : "") + names[i];
    return text + "}";
}

}  // namespace

uint32_t PassView::findSorted(const variants::VariantKey& masked) const {
    uint32_t words = field(pack::kPassKeyWords);
    uint32_t count = field(pack::kPassVariantCount);
    const std::byte* keys =
        mImage->raw(Chunk::VariantKeys).data() + 8 * size_t{field(pack::kPassKeyFirst)};
    if (words == 1) {
        const detail::KeyHashIndex& index = mImage->keyIndex(mRecord);
        if (!index.empty()) return index.find(masked.words()[0]);
        return findOneWord(keys, count, masked.words()[0]);
    }
    return findWords(keys, count, words, masked.words().data());
}

Result<VariantView> PassView::lookup(const variants::VariantKey& key,
                                     variants::SelectionPolicy policy) const {
    variants::VariantKey requested = pack::maskKeyToTable(key, keywordCount());
    uint32_t sorted = findSorted(requested);
    if (sorted != pack::kNone) return VariantView(mImage, mShader, mRecord, sorted, true);
    return lookupMiss(requested, policy);
}

Result<VariantView> PassView::lookup(std::span<const std::string_view> keywords,
                                     variants::SelectionPolicy policy) const {
    return lookup(keyOf(keywords), policy);
}

Result<VariantView> PassView::lookup(const std::vector<std::string>& keywords,
                                     variants::SelectionPolicy policy) const {
    return lookup(keyOf(keywords), policy);
}

Result<VariantView> PassView::lookup(const variants::LightDescription& light,
                                     variants::SelectionPolicy policy,
                                     const variants::VariantKey& materialKey) const {
    std::optional<variants::LightPassKind> kind = variants::lightPassKindFromLightMode(lightMode());
    if (!kind) {
        return makeError(ErrorCode::InvalidInput,
                         describe() + " is not a light pass (ForwardBase, ForwardAdd, Deferred)");
    }
    variants::VariantKey key = keyOf(variants::lightKeywords(light, *kind));
    for (size_t w = 0; w < key.words().size(); ++w) key.words()[w] |= materialKey.words()[w];
    return lookup(key, policy);
}

// No exact match: the variants module decides, over the keys in enumeration order.
Result<VariantView> PassView::lookupMiss(const variants::VariantKey& requested,
                                         variants::SelectionPolicy policy) const {
    const std::vector<variants::VariantKey>& keys = mImage->enumerationKeys(mRecord);
    variants::Selection selection = variants::selectVariant(keys, requested, policy);
    if (selection.index && *selection.index < keys.size()) {
        uint32_t record = field(pack::kPassVariantFirst) + static_cast<uint32_t>(*selection.index);
        uint32_t sorted = mImage->get(Chunk::VariantOrder, record, pack::kOrderPosition);
        return VariantView(mImage, mShader, mRecord, sorted, false);
    }
    std::string message = "no variant of " + describe() + " for " + braced(keywordsOf(requested)) +
                          " (policy " + variants::toString(policy) + ")";
    if (!selection.nearest.empty()) {
        message += "; nearest:";
        for (size_t index : selection.nearest) {
            if (index < keys.size()) message += " " + braced(keywordsOf(keys[index]));
        }
    }
    return makeError(ErrorCode::NotFound, message);
}

}  // namespace varc::reader
