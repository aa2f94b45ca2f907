// SPDX-License-Identifier: Apache-2.0
// VariantKey: set operations, ordering and hashing of the 256-bit keyword mask.
#include "varc/variants/VariantKey.h"

#include <bit>

#include "varc/core/Check.h"

namespace varc::variants {

void VariantKey::set(size_t bit) {
    VARC_CHECK(bit < kMaxKeywords) << "VariantKey bit " << bit << " out of range";
    mWords[bit / 64] |= uint64_t{1} << (bit % 64);
}

void VariantKey::reset(size_t bit) {
    VARC_CHECK(bit < kMaxKeywords) << "VariantKey bit " << bit << " out of range";
    mWords[bit / 64] &= ~(uint64_t{1} << (bit % 64));
}

bool VariantKey::test(size_t bit) const {
    VARC_CHECK(bit < kMaxKeywords) << "VariantKey bit " << bit << " out of range";
    return (mWords[bit / 64] >> (bit % 64)) & 1u;
}

size_t VariantKey::count() const {
    size_t total = 0;
    for (uint64_t word : mWords) total += static_cast<size_t>(std::popcount(word));
    return total;
}

VariantKey VariantKey::operator&(const VariantKey& other) const {
    VariantKey result;
    for (size_t i = 0; i < mWords.size(); ++i) result.mWords[i] = mWords[i] & other.mWords[i];
    return result;
}

VariantKey VariantKey::operator|(const VariantKey& other) const {
    VariantKey result;
    for (size_t i = 0; i < mWords.size(); ++i) result.mWords[i] = mWords[i] | other.mWords[i];
    return result;
}

VariantKey VariantKey::andNot(const VariantKey& other) const {
    VariantKey result;
    for (size_t i = 0; i < mWords.size(); ++i) result.mWords[i] = mWords[i] & ~other.mWords[i];
    return result;
}

bool operator<(const VariantKey& a, const VariantKey& b) {
    for (size_t i = a.mWords.size(); i-- > 0;) {
        if (a.mWords[i] != b.mWords[i]) return a.mWords[i] < b.mWords[i];
    }
    return false;
}

// Each word goes through a splitmix64 finaliser before it is folded in, so keys that differ in
// one high bit still spread over the whole hash.
size_t VariantKey::hash() const {
    uint64_t h = 0x9e3779b97f4a7c15ull;
    for (uint64_t word : mWords) {
        uint64_t z = word + h;
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
        h = (h * 31) ^ (z ^ (z >> 31));
    }
    return static_cast<size_t>(h);
}

}  // namespace varc::variants
