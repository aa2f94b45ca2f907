// SPDX-License-Identifier: Apache-2.0
// Every chunk of a pack under construction: the string pool, table builders and raw chunks.
#include "TableSet.h"

#include "varc/core/Check.h"
#include "varc/pack/PackTables.h"

namespace varc::packwriter {

TableSet::TableSet() {
    for (size_t i = 0; i < pack::kChunkCount; ++i) {
        auto chunk = static_cast<pack::Chunk>(i);
        if (pack::chunkInfo(chunk).table && chunk != pack::Chunk::Strings) {
            mTables[i].emplace(static_cast<uint32_t>(pack::tableSchema(chunk).size()));
        }
    }
}

TableBuilder& TableSet::table(pack::Chunk chunk) {
    auto& table = mTables[static_cast<size_t>(chunk)];
    VARC_CHECK(table.has_value()) << pack::chunkInfo(chunk).name << " is not a table builder";
    return *table;
}

std::string& TableSet::raw(pack::Chunk chunk) {
    VARC_CHECK(!pack::chunkInfo(chunk).table) << pack::chunkInfo(chunk).name << " is a table";
    VARC_CHECK(chunk != pack::Chunk::StringBytes) << "StringBytes comes from the string pool";
    return mRaw[static_cast<size_t>(chunk)];
}

std::vector<std::pair<pack::Chunk, std::string>> TableSet::finish() const {
    std::vector<std::pair<pack::Chunk, std::string>> chunks;
    for (size_t i = 0; i < pack::kChunkCount; ++i) {
        auto chunk = static_cast<pack::Chunk>(i);
        const pack::ChunkInfo& info = pack::chunkInfo(chunk);
        if (chunk == pack::Chunk::Strings) {
            chunks.emplace_back(chunk, mStrings.stringsChunk());
        } else if (chunk == pack::Chunk::StringBytes) {
            chunks.emplace_back(chunk, mStrings.bytesChunk());
        } else if (info.table) {
            // An optional table without records is left out (packs without it stay 1.0-shaped).
            if (info.required || mTables[i]->size() > 0) {
                chunks.emplace_back(chunk, mTables[i]->serialize());
            }
        } else if (info.required || !mRaw[i].empty()) {
            chunks.emplace_back(chunk, mRaw[i]);
        }
    }
    return chunks;
}

}  // namespace varc::packwriter
