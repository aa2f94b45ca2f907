// SPDX-License-Identifier: Apache-2.0
// One preprocessor directive line, classified for include splicing, guards and pragmas.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace varc::includes {

enum class DirectiveKind {
    Other,             // #define of no interest, #undef, #error, #line, the null directive, ...
    Include,           // #include "x" / <x> / #include_with_pragmas "x"
    MalformedInclude,  // an #include whose name cannot be read; see |error|
    Pragma,            // #pragma ...
    If,                // #if
    Ifdef,             // #ifdef
    Ifndef,            // #ifndef
    Else,              // #else, #elif, #elifdef, #elifndef
    Endif,             // #endif
    Define,            // #define
};

// Offsets are byte offsets into the scanned text (not into the comment-stripped code), so they
// convert directly to line and column.
struct Directive {
    DirectiveKind kind = DirectiveKind::Other;
    size_t hashOffset = 0;  // the '#'
    // Include: the name as written, without quotes. Pragma: the text after "pragma", trimmed.
    // Ifndef / Define: the macro name. If: X when the condition is exactly !defined(X) or
    // !defined X (an include guard candidate), else empty.
    std::string argument;
    bool angled = false;        // Include: <name> rather than "name"
    bool withPragmas = false;   // Include: #include_with_pragmas
    size_t argumentOffset = 0;  // Include: the opening quote or '<'; Malformed: the error spot
    std::string error;          // MalformedInclude: what is wrong
    std::optional<size_t> extraTokensOffset;  // Include: first token after the name, if any
};

// Classifies a directive line. |code| is the logical line with comments replaced by spaces and
// continuations removed; its first non-blank character is '#'. |offsets[i]| is the text offset
// of |code[i]|. Example: `#  include "My Lighting.cginc"` gives {Include, "My Lighting.cginc",
// argumentOffset = offset of the '"'}; `#include` alone gives MalformedInclude with error
// `expected "FILENAME" or <FILENAME> after #include` at the end of the line.
Directive parseDirective(std::string_view code, const std::vector<size_t>& offsets);

}  // namespace varc::includes
