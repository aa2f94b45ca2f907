// SPDX-License-Identifier: Apache-2.0
// Maps byte offsets in a file to 1-based line and column numbers.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "varc/core/SourceLocation.h"

namespace varc::shaderlab {

// Built once per file; lookups are a binary search over line starts. Columns count bytes and a
// tab counts as one column, so "\tPass" has `Pass` at column 2.
class LineIndex {
public:
    LineIndex(std::string_view text, FileId file);

    // Location of byte |offset| (0-based); |offset| may equal the text size (end of file).
    // Example: in "ab\ncd", offset 1 -> 1:2 and offset 3 -> 2:1.
    SourceLocation locationOf(size_t offset) const;

private:
    std::vector<size_t> mLineStarts;  // offset of the first byte of each line
    FileId mFile;
};

}  // namespace varc::shaderlab
