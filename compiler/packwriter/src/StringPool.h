// SPDX-License-Identifier: Apache-2.0
// Interns the pack's strings; ids follow first-intern order, so equal inputs give equal ids.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace varc::packwriter {

class StringPool {
public:
    StringPool();  // interns "" as id 0

    // The id of |text|, adding it on first use.
    uint32_t intern(std::string_view text);

    // The Strings table chunk (offset, length per id) and the StringBytes raw chunk.
    std::string stringsChunk() const;
    const std::string& bytesChunk() const { return mBytes; }

private:
    std::unordered_map<std::string, uint32_t> mIds;
    std::vector<std::pair<uint32_t, uint32_t>> mSpans;  // offset, length per id
    std::string mBytes;
};

}  // namespace varc::packwriter
