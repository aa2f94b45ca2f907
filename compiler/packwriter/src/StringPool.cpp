// SPDX-License-Identifier: Apache-2.0
// Interns the pack's strings; ids follow first-intern order, so equal inputs give equal ids.
#include "StringPool.h"

#include "TableBuilder.h"
#include "varc/core/Check.h"
#include "varc/pack/PackTables.h"

namespace varc::packwriter {

StringPool::StringPool() { intern(""); }

uint32_t StringPool::intern(std::string_view text) {
    auto [it, inserted] = mIds.try_emplace(std::string(text), 0);
    if (!inserted) return it->second;
    VARC_CHECK(mBytes.size() + text.size() <= UINT32_MAX) << "pack strings exceed 4 GiB";
    VARC_CHECK(mSpans.size() < pack::kNone) << "too many pack strings";
    it->second = static_cast<uint32_t>(mSpans.size());
    mSpans.emplace_back(static_cast<uint32_t>(mBytes.size()), static_cast<uint32_t>(text.size()));
    mBytes.append(text);
    return it->second;
}

std::string StringPool::stringsChunk() const {
    TableBuilder table(pack::kStringFieldCount);
    for (const auto& [offset, length] : mSpans) table.add({offset, length});
    return table.serialize();
}

}  // namespace varc::packwriter
