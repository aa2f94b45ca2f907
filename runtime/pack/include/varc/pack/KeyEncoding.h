// SPDX-License-Identifier: Apache-2.0
// The on-disk encoding of VariantKey: a pass's keys as 1-4 little-endian u64 words, sorted.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "varc/pack/LittleEndian.h"
#include "varc/variants/VariantKey.h"

namespace varc::pack {

// Each pass stores its keys with keyWordCount(keywordTable.size()) words, word 0 holding bits
// 0..63. A pass with 20 keywords uses 1 word (8 bytes per key); 130 keywords use 3 words.
inline constexpr uint32_t kMaxKeyWords = variants::VariantKey::kMaxKeywords / 64;

constexpr uint32_t keyWordCount(size_t keywordCount) {
    return keywordCount <= 64 ? 1u : static_cast<uint32_t>((keywordCount + 63) / 64);
}

// The sort order of the index: compare words from the highest down, unsigned (the same order
// as VariantKey's operator<). Returns <0, 0 or >0. |a| and |b| hold |words| host-order words.
inline int compareKeyWords(const uint64_t* a, const uint64_t* b, uint32_t words) {
    for (uint32_t i = words; i-- > 0;) {
        if (a[i] != b[i]) return a[i] < b[i] ? -1 : 1;
    }
    return 0;
}

// The bits of word |word| that a table of |keywordCount| keywords can use.
constexpr uint64_t allowedBits(size_t keywordCount, size_t word) {
    if (keywordCount >= (word + 1) * 64) return ~uint64_t{0};
    if (keywordCount <= word * 64) return 0;
    return (uint64_t{1} << (keywordCount - word * 64)) - 1;
}

// True when |key| has no bit at or above |keywordCount|.
inline bool keyFitsTable(const variants::VariantKey& key, size_t keywordCount) {
    const auto& words = key.words();
    for (size_t i = 0; i < words.size(); ++i) {
        if ((words[i] & ~allowedBits(keywordCount, i)) != 0) return false;
    }
    return true;
}

// |key| restricted to the first |keywordCount| bits (Unity: requested ∩ declared).
inline variants::VariantKey maskKeyToTable(const variants::VariantKey& key, size_t keywordCount) {
    variants::VariantKey masked;
    for (size_t i = 0; i < masked.words().size(); ++i) {
        masked.words()[i] = key.words()[i] & allowedBits(keywordCount, i);
    }
    return masked;
}

// Appends the |words| low words of |key|.
inline void appendKey(std::string& out, const variants::VariantKey& key, uint32_t words) {
    for (uint32_t i = 0; i < words; ++i) appendU64(out, key.words()[i]);
}

// Reads a key of |words| words at |p| (bounds checked by the caller).
inline variants::VariantKey loadKey(const std::byte* p, uint32_t words) {
    variants::VariantKey key;
    for (uint32_t i = 0; i < words; ++i) key.words()[i] = loadU64(p + 8 * i);
    return key;
}

}  // namespace varc::pack
