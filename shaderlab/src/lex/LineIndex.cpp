// SPDX-License-Identifier: Apache-2.0
// Maps byte offsets in a file to 1-based line and column numbers.
#include "lex/LineIndex.h"

#include <algorithm>

namespace varc::shaderlab {

LineIndex::LineIndex(std::string_view text, FileId file) : mFile(file) {
    mLineStarts.push_back(0);
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '\n') mLineStarts.push_back(i + 1);
    }
}

SourceLocation LineIndex::locationOf(size_t offset) const {
    // The last line start that is <= offset; mLineStarts[0] == 0, so it always exists.
    auto next = std::upper_bound(mLineStarts.begin(), mLineStarts.end(), offset);
    size_t lineIndex = static_cast<size_t>(next - mLineStarts.begin()) - 1;
    size_t column = offset - mLineStarts[lineIndex] + 1;
    return SourceLocation{mFile, static_cast<uint32_t>(lineIndex + 1),
                          static_cast<uint32_t>(column)};
}

}  // namespace varc::shaderlab
