// SPDX-License-Identifier: Apache-2.0
// sampleEvenly: the sample's size, spread, order and ends.
#include <gtest/gtest.h>

#include "varc/variants/VariantSample.h"

namespace varc::variants {
namespace {

// Keys 0..n-1, each with one bit: key i has bit i, so a sample's bits name its positions.
std::vector<VariantKey> numberedKeys(size_t n) {
    std::vector<VariantKey> keys(n);
    for (size_t i = 0; i < n; ++i) keys[i].set(i);
    return keys;
}

std::vector<size_t> positionsOf(const std::vector<VariantKey>& sample) {
    std::vector<size_t> positions;
    for (const VariantKey& key : sample) {
        for (size_t bit = 0; bit < VariantKey::kMaxKeywords; ++bit) {
            if (key.test(bit)) positions.push_back(bit);
        }
    }
    return positions;
}

TEST(VariantSample, KeepsEveryKeyWhenTheCountCoversThemOrIsZero) {
    EXPECT_EQ(positionsOf(sampleEvenly(numberedKeys(5), 5)), (std::vector<size_t>{0, 1, 2, 3, 4}));
    EXPECT_EQ(positionsOf(sampleEvenly(numberedKeys(5), 9)), (std::vector<size_t>{0, 1, 2, 3, 4}));
    EXPECT_EQ(positionsOf(sampleEvenly(numberedKeys(5), 0)), (std::vector<size_t>{0, 1, 2, 3, 4}));
    EXPECT_TRUE(sampleEvenly({}, 3).empty());
}

TEST(VariantSample, SpreadsEvenlyFromTheFirstToTheLast) {
    EXPECT_EQ(positionsOf(sampleEvenly(numberedKeys(10), 4)), (std::vector<size_t>{0, 3, 6, 9}));
    EXPECT_EQ(positionsOf(sampleEvenly(numberedKeys(10), 2)), (std::vector<size_t>{0, 9}));
    EXPECT_EQ(positionsOf(sampleEvenly(numberedKeys(10), 1)), (std::vector<size_t>{0}));
}

TEST(VariantSample, IsStrictlyIncreasingAndOfTheRequestedSize) {
    for (size_t n : {2u, 7u, 64u, 200u}) {
        for (uint64_t count = 1; count < n; ++count) {
            std::vector<size_t> positions = positionsOf(sampleEvenly(numberedKeys(n), count));
            ASSERT_EQ(positions.size(), count) << n << " " << count;
            for (size_t i = 1; i < positions.size(); ++i) {
                ASSERT_LT(positions[i - 1], positions[i]) << n << " " << count;
            }
            if (count >= 2) {
                EXPECT_EQ(positions.back(), n - 1);
            }
        }
    }
}

}  // namespace
}  // namespace varc::variants
