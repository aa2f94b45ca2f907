// SPDX-License-Identifier: Apache-2.0
// The shared format headers: byte order, key encoding and order, and schema consistency.
#include <gtest/gtest.h>

#include <set>

#include "varc/pack/KeyEncoding.h"
#include "varc/pack/LittleEndian.h"
#include "varc/pack/PackTables.h"

namespace varc {
namespace {

TEST(PackFormat, LittleEndianStoresLowByteFirst) {
    std::string out;
    pack::appendU32(out, 0x04030201u);
    pack::appendU64(out, 0x0807060504030201ull);
    pack::appendU16(out, 0x0201);
    ASSERT_EQ(out.size(), 14u);
    EXPECT_EQ(out.substr(0, 4), std::string("\x01\x02\x03\x04", 4));
    auto bytes = reinterpret_cast<const std::byte*>(out.data());
    EXPECT_EQ(pack::loadU32(bytes), 0x04030201u);
    EXPECT_EQ(pack::loadU64(bytes + 4), 0x0807060504030201ull);
    EXPECT_EQ(pack::loadU16(bytes + 12), 0x0201);
    EXPECT_EQ(pack::floatFromBits(pack::floatBits(-2.5f)), -2.5f);
}

TEST(PackFormat, KeyWordCountCoversTheTable) {
    EXPECT_EQ(pack::keyWordCount(0), 1u);
    EXPECT_EQ(pack::keyWordCount(64), 1u);
    EXPECT_EQ(pack::keyWordCount(65), 2u);
    EXPECT_EQ(pack::keyWordCount(256), 4u);
}

TEST(PackFormat, KeyOrderMatchesVariantKeyOrder) {
    std::vector<variants::VariantKey> keys(6);
    keys[1].words()[0] = 1;
    keys[2].words()[0] = ~uint64_t{0};
    keys[3].words()[1] = 1;
    keys[4].words()[1] = 1;
    keys[4].words()[0] = 5;
    keys[5].words()[3] = 1;
    for (const auto& a : keys) {
        for (const auto& b : keys) {
            int order = pack::compareKeyWords(a.words().data(), b.words().data(), 4);
            EXPECT_EQ(order < 0, a < b);
            EXPECT_EQ(order == 0, a == b);
        }
    }
}

TEST(PackFormat, MaskAndFitUseOnlyTableBits) {
    variants::VariantKey key;
    key.words()[0] = 0b1011;
    key.words()[1] = 1;
    EXPECT_FALSE(pack::keyFitsTable(key, 3));
    EXPECT_TRUE(pack::keyFitsTable(key, 65));
    variants::VariantKey masked = pack::maskKeyToTable(key, 3);
    EXPECT_EQ(masked.words()[0], 0b011u);
    EXPECT_EQ(masked.words()[1], 0u);
    std::string out;
    pack::appendKey(out, key, 2);
    EXPECT_EQ(pack::loadKey(reinterpret_cast<const std::byte*>(out.data()), 2), key);
}

TEST(PackFormat, EveryRangeIsAFirstFollowedByACount) {
    for (size_t c = 0; c < pack::kChunkCount; ++c) {
        auto schema = pack::tableSchema(static_cast<pack::Chunk>(c));
        EXPECT_EQ(schema.empty(), !pack::kChunkInfo[c].table) << pack::kChunkInfo[c].name;
        for (size_t f = 0; f < schema.size(); ++f) {
            bool isFirst = schema[f].kind == pack::FieldKind::First;
            bool nextIsCount =
                f + 1 < schema.size() && schema[f + 1].kind == pack::FieldKind::Count;
            bool prevIsFirst = f > 0 && schema[f - 1].kind == pack::FieldKind::First;
            if (isFirst) {
                EXPECT_TRUE(nextIsCount) << pack::kChunkInfo[c].name << " field " << f;
            }
            if (schema[f].kind == pack::FieldKind::Count) {
                EXPECT_TRUE(prevIsFirst) << pack::kChunkInfo[c].name << " field " << f;
            }
            if (schema[f].kind == pack::FieldKind::Index || isFirst) {
                EXPECT_TRUE(pack::chunkInfo(schema[f].target).table);
            }
        }
    }
}

TEST(PackFormat, ChunkIdsAreUniqueAndNamed) {
    std::set<uint32_t> ids;
    for (const pack::ChunkInfo& info : pack::kChunkInfo) {
        EXPECT_TRUE(ids.insert(info.fourcc).second) << info.name;
        EXPECT_EQ(info.fourcc,
                  pack::makeFourcc({info.name[0], info.name[1], info.name[2], info.name[3], '\0'}));
    }
}

TEST(PackFormat, RenderStateSchemaCoversEverySlot) {
    EXPECT_EQ(pack::kRenderStateSchema.size(), pack::kRenderStateFieldCount);
    int visited = 0;
    pack::PackRenderState state;
    pack::forEachStateField(state, [&](uint32_t slot, auto&) { EXPECT_EQ(slot, visited++); });
    EXPECT_EQ(visited, static_cast<int>(pack::kRsSlotCount));
}

}  // namespace
}  // namespace varc
