// SPDX-License-Identifier: Apache-2.0
// Every chunk of a pack under construction: the string pool, table builders and raw chunks.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "StringPool.h"
#include "TableBuilder.h"
#include "varc/pack/PackFormat.h"

namespace varc::packwriter {

class TableSet {
public:
    TableSet();

    StringPool& strings() { return mStrings; }
    // The builder of table chunk |chunk| (a VARC_CHECK failure for raw chunks).
    TableBuilder& table(pack::Chunk chunk);
    // The bytes of raw chunk |chunk| (a VARC_CHECK failure for table chunks).
    std::string& raw(pack::Chunk chunk);

    // The serialized chunks in Chunk order. Optional chunks left empty are omitted.
    std::vector<std::pair<pack::Chunk, std::string>> finish() const;

private:
    StringPool mStrings;
    std::array<std::optional<TableBuilder>, pack::kChunkCount> mTables;
    std::array<std::string, pack::kChunkCount> mRaw;
};

}  // namespace varc::packwriter
