// SPDX-License-Identifier: Apache-2.0
// The hash index over sorted one-word keys that Pack::open builds for large passes.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "KeyHashIndex.h"
#include "varc/pack/LittleEndian.h"

namespace varc::reader::detail {
namespace {

// |count| distinct sorted keys with few bits set, like variant keys.
std::string sortedKeys(uint32_t count) {
    std::set<uint64_t> keys;
    for (uint64_t i = 0; keys.size() < count; ++i)
        keys.insert((i * 0x9e3779b97f4a7c15ULL) & 0x0000'0fff'00ff'0f0fULL);
    std::string bytes;
    for (uint64_t key : keys) pack::appendU64(bytes, key);
    return bytes;
}

TEST(KeyHashIndex, FindsEveryKeyAtItsSortedPosition) {
    std::string bytes = sortedKeys(5000);
    auto keys = reinterpret_cast<const std::byte*>(bytes.data());
    KeyHashIndex index(keys, 5000);
    ASSERT_FALSE(index.empty());
    for (uint32_t i = 0; i < 5000; ++i) {
        ASSERT_EQ(index.find(pack::loadU64(keys + 8 * size_t{i})), i);
    }
}

TEST(KeyHashIndex, MissesReturnNone) {
    std::string bytes = sortedKeys(200);
    auto keys = reinterpret_cast<const std::byte*>(bytes.data());
    KeyHashIndex index(keys, 200);
    std::set<uint64_t> present;
    for (uint32_t i = 0; i < 200; ++i) present.insert(pack::loadU64(keys + 8 * size_t{i}));
    int misses = 0;
    for (uint64_t probe = 1; misses < 1000; probe = probe * 3 + 1) {
        if (present.count(probe)) continue;
        ++misses;
        ASSERT_EQ(index.find(probe), UINT32_MAX) << probe;
    }
}

TEST(KeyHashIndex, DefaultIsEmpty) { EXPECT_TRUE(KeyHashIndex().empty()); }

}  // namespace
}  // namespace varc::reader::detail
