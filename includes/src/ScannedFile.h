// SPDX-License-Identifier: Apache-2.0
// A source text split into logical lines, with its directives and include guard.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "Directive.h"

namespace varc::includes {

// Physical lines joined by backslash continuations. Comments do not join lines here; they only
// carry the "inside /* */" state from one line to the next.
struct LogicalLine {
    uint32_t firstLine = 0;  // 0-based index of the first physical line
    uint32_t lastLine = 0;   // 0-based index of the last physical line (continuations)
    bool blank = true;       // nothing but blanks and comments
    bool isDirective = false;
    Directive directive;  // meaningful when |isDirective|
    // A `/* */` comment is open at the start (the line continues a comment) or at the end.
    // The offsets let an include line be replaced without eating or losing the comment:
    // |commentTailEnd| is just past the "*/" that closes the first, |openCommentBegin| is the
    // "/*" of the second.
    bool startsInComment = false;
    size_t commentTailEnd = 0;
    bool endsInComment = false;
    size_t openCommentBegin = 0;
};

enum class GuardKind { None, PragmaOnce, Macro };

// How a file protects itself from double inclusion. For Macro guards, |openLine| and
// |closeLine| index the `#ifndef X` / `#if !defined(X)` and the final `#endif` in |lines|.
struct IncludeGuard {
    GuardKind kind = GuardKind::None;
    std::string macro;
    size_t openLine = 0;
    size_t closeLine = 0;
};

// The scan of one text. |text| is borrowed: it must outlive this object (SourceMap contents
// never move, and roots live for the whole expansion).
struct ScannedFile {
    struct Position {
        uint32_t lineIndex;  // 0-based physical line
        uint32_t column;     // 1-based byte column
    };

    std::string_view text;
    std::vector<size_t> lineStarts;  // text offset of each physical line
    std::vector<LogicalLine> lines;
    IncludeGuard guard;
    std::optional<size_t> unterminatedComment;  // offset of a "/*" never closed

    // Physical line |index| without its "\n" or "\r\n".
    std::string_view physicalLine(uint32_t index) const;
    // Line and column of text offset |offset| (an offset at a line's end is its last column+1).
    Position position(size_t offset) const;
};

}  // namespace varc::includes
