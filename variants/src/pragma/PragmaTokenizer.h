// SPDX-License-Identifier: Apache-2.0
// Splits a pragma line into blank-separated tokens that carry their own source columns.
#pragma once

#include <string_view>
#include <vector>

#include "varc/core/PragmaLine.h"
#include "varc/core/SourceLocation.h"

namespace varc::variants {

struct PragmaToken {
    std::string_view text;    // views into the PragmaLine's text
    SourceLocation location;  // column of the token's first character
};

// Splits |line|.text at spaces and tabs. Columns assume the usual spelling `#pragma ` (one
// blank after "pragma"), because PragmaLine keeps only the '#' location: a token at offset k of
// the text is at column hash + 8 + k. Unknown columns (0) stay 0.
// Example: '#' at column 13, text "multi_compile _ A" -> tokens at columns 21, 35, 37.
std::vector<PragmaToken> tokenizePragma(const PragmaLine& line);

// True for `_`, `__`, ...: Unity's no-keyword entry.
bool isAllUnderscores(std::string_view token);
// True for a C identifier: [A-Za-z_][A-Za-z0-9_]*.
bool isIdentifier(std::string_view token);

}  // namespace varc::variants
