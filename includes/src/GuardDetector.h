// SPDX-License-Identifier: Apache-2.0
// Recognises include guards: `#pragma once` and the #ifndef/#define/#endif idiom.
#pragma once

#include <vector>

#include "ScannedFile.h"

namespace varc::includes {

// Returns how |lines| guard themselves against double inclusion:
//  * PragmaOnce when the first non-blank line is `#pragma once`;
//  * Macro when the first non-blank line is `#ifndef X`, `#if !defined(X)` or `#if !defined X`,
//    the next non-blank line is `#define X`, the matching `#endif` (with no top-level
//    #else/#elif) is the last non-blank line;
//  * None otherwise. Blank means blanks and comments only.
// Example: "// c\n#ifndef A_H\n#define A_H\nint a;\n#endif // A_H\n" is a Macro guard on A_H
// with openLine 1 and closeLine 4.
IncludeGuard detectIncludeGuard(const std::vector<LogicalLine>& lines);

}  // namespace varc::includes
