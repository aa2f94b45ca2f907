// SPDX-License-Identifier: Apache-2.0
// CacheBundle: entries round-trip through a bundle's bytes, and a damaged index yields the slots
// before the damage, never one outside the file.
#include <gtest/gtest.h>

#include "varc/cache/CacheBundle.h"

namespace varc::cache {
namespace {

std::string valueAt(const std::string& bytes, const BundleSlot& slot) {
    return bytes.substr(slot.offset, slot.length);
}

TEST(CacheBundleTest, EntriesRoundTrip) {
    std::vector<CacheEntry> entries = {{"a.program", "first"}, {"b.source", ""}, {"c", "third!"}};
    std::string bytes = encodeBundle(entries);
    ASSERT_EQ(bundleIndexEnd(bytes.substr(0, kBundleHeaderBytes)),
              bytes.size() - std::string("firstthird!").size());
    std::vector<BundleSlot> slots = decodeBundleIndex(bytes, bytes.size());
    ASSERT_EQ(slots.size(), 3u);
    for (size_t i = 0; i < 3; ++i) {
        EXPECT_EQ(slots[i].key, entries[i].key);
        EXPECT_EQ(valueAt(bytes, slots[i]), entries[i].value);
    }
}

TEST(CacheBundleTest, NotABundleHasNoIndex) {
    EXPECT_EQ(bundleIndexEnd(""), 0u);
    EXPECT_EQ(bundleIndexEnd("VARCBDL1"), 0u) << "too short for the header";
    EXPECT_EQ(bundleIndexEnd("NOTABNDL12345678"), 0u);
    EXPECT_TRUE(decodeBundleIndex("garbage", 7).empty());
}

TEST(CacheBundleTest, ADamagedIndexKeepsOnlySoundSlots) {
    std::vector<CacheEntry> entries = {{"a", "0123456789"}, {"b", "abcdefghij"}};
    std::string bytes = encodeBundle(entries);
    // The file is shorter than the index promises: the second value lies outside it.
    std::vector<BundleSlot> slots = decodeBundleIndex(bytes, bytes.size() - 5);
    ASSERT_EQ(slots.size(), 1u);
    EXPECT_EQ(slots[0].key, "a");
    // The index cut in the middle of its second slot: only the first is read.
    const size_t firstSlotEnd = kBundleHeaderBytes + 2 + 1 + 8 + 4;
    std::string cut = bytes;
    cut[kBundleHeaderBytes - 4] = static_cast<char>(firstSlotEnd + 5 - kBundleHeaderBytes);
    slots = decodeBundleIndex(cut, cut.size());
    ASSERT_EQ(slots.size(), 1u);
    EXPECT_EQ(slots[0].key, "a");
    // Every prefix of the bytes decodes without reading past it.
    for (size_t length = 0; length <= bytes.size(); ++length) {
        for (const BundleSlot& slot : decodeBundleIndex(bytes.substr(0, length), length)) {
            EXPECT_LE(slot.offset + slot.length, length);
        }
    }
}

}  // namespace
}  // namespace varc::cache
