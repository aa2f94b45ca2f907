// SPDX-License-Identifier: Apache-2.0
// Line and column lookups on a scanned text.
#include "ScannedFile.h"

#include <algorithm>

#include "varc/core/Check.h"

namespace varc::includes {

std::string_view ScannedFile::physicalLine(uint32_t index) const {
    VARC_CHECK(index < lineStarts.size()) << "line index " << index << " out of range";
    size_t begin = lineStarts[index];
    size_t end = index + 1 < lineStarts.size() ? lineStarts[index + 1] : text.size();
    if (end > begin && text[end - 1] == '\n') --end;
    if (end > begin && text[end - 1] == '\r') --end;
    return text.substr(begin, end - begin);
}

ScannedFile::Position ScannedFile::position(size_t offset) const {
    VARC_CHECK(!lineStarts.empty()) << "position in an empty text";
    auto next = std::upper_bound(lineStarts.begin(), lineStarts.end(), offset);
    auto index = static_cast<size_t>(next - lineStarts.begin()) - 1;
    return {static_cast<uint32_t>(index), static_cast<uint32_t>(offset - lineStarts[index] + 1)};
}

}  // namespace varc::includes
