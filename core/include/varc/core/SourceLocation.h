// SPDX-License-Identifier: Apache-2.0
// A position in a source file, identified by the file's id in a SourceMap.
#pragma once

#include <cstdint>

namespace varc {

// Identifies a file registered with includes::SourceMap. kNoFile means "no file known".
using FileId = uint32_t;
inline constexpr FileId kNoFile = 0xffffffffu;

// 1-based line and column; 0 means unknown (glslang, for example, reports no columns).
struct SourceLocation {
    FileId file = kNoFile;
    uint32_t line = 0;
    uint32_t column = 0;

    bool isKnown() const { return file != kNoFile; }
    friend bool operator==(const SourceLocation&, const SourceLocation&) = default;
};

}  // namespace varc
