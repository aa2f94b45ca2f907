// SPDX-License-Identifier: Apache-2.0
// VariantKey: bit operations across words, ordering, hashing.
#include <gtest/gtest.h>

#include <type_traits>
#include <unordered_set>

#include "varc/variants/VariantKey.h"

namespace varc::variants {
namespace {

VariantKey keyWith(std::initializer_list<size_t> bits) {
    VariantKey key;
    for (size_t bit : bits) key.set(bit);
    return key;
}

TEST(VariantKey, IsTriviallyCopyableAndFixedSize) {
    EXPECT_TRUE(std::is_trivially_copyable_v<VariantKey>);
    EXPECT_EQ(sizeof(VariantKey), 32u);
}

TEST(VariantKey, SetTestResetAcrossAllWords) {
    VariantKey key;
    EXPECT_TRUE(key.empty());
    for (size_t bit : {0u, 63u, 64u, 127u, 128u, 255u}) {
        EXPECT_FALSE(key.test(bit));
        key.set(bit);
        EXPECT_TRUE(key.test(bit));
    }
    EXPECT_EQ(key.count(), 6u);
    EXPECT_EQ(key.words()[1], (uint64_t{1} << 63) | 1u);
    key.reset(64);
    EXPECT_FALSE(key.test(64));
    EXPECT_TRUE(key.test(63));
    EXPECT_EQ(key.count(), 5u);
}

TEST(VariantKey, SetIsIdempotent) {
    VariantKey key = keyWith({5, 5, 5});
    EXPECT_EQ(key.count(), 1u);
}

TEST(VariantKey, AndOrAndNot) {
    VariantKey a = keyWith({1, 70, 200});
    VariantKey b = keyWith({70, 130});
    EXPECT_EQ(a & b, keyWith({70}));
    EXPECT_EQ(a | b, keyWith({1, 70, 130, 200}));
    EXPECT_EQ(a.andNot(b), keyWith({1, 200}));
    EXPECT_EQ(b.andNot(a), keyWith({130}));
}

TEST(VariantKey, OrderComparesHighestWordFirst) {
    VariantKey low = keyWith({0, 1, 2, 63});
    VariantKey high = keyWith({200});
    EXPECT_TRUE(low < high);
    EXPECT_FALSE(high < low);
    EXPECT_FALSE(low < low);
    EXPECT_TRUE(keyWith({3}) < keyWith({4}));
    EXPECT_TRUE(VariantKey{} < keyWith({0}));
}

TEST(VariantKey, EqualKeysHashEqualAndSingleBitsHashApart) {
    EXPECT_EQ(keyWith({9, 100}).hash(), keyWith({100, 9}).hash());
    std::unordered_set<size_t> hashes;
    for (size_t bit = 0; bit < VariantKey::kMaxKeywords; ++bit)
        hashes.insert(keyWith({bit}).hash());
    hashes.insert(VariantKey{}.hash());
    EXPECT_EQ(hashes.size(), VariantKey::kMaxKeywords + 1);
    EXPECT_EQ(std::hash<VariantKey>{}(keyWith({3})), keyWith({3}).hash());
}

}  // namespace
}  // namespace varc::variants
