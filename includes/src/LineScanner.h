// SPDX-License-Identifier: Apache-2.0
// Splits source text into logical lines, telling directives from comments and strings.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "ScannedFile.h"

namespace varc::includes {

// A single pass over a text, C translation phases 2-3 style: backslash-newline joins lines,
// `//` and `/* */` comments count as one blank, and a line is a directive when its first token
// is '#'. String literals and the header name of an #include are read whole, so
// `#include "a//b.h"` keeps its name. Example: scanning
//     "/* #include \"x\" */\n#  include <My File.h> // note\n"
// gives two logical lines; only the second is a directive (Include "My File.h").
class LineScanner {
public:
    // Scans |text|, which the result borrows, and detects its include guard.
    static ScannedFile scan(std::string_view text);

private:
    enum class Mode { Code, LineComment, BlockComment, String, HeaderName };

    explicit LineScanner(std::string_view text) : mText(text) {}
    LogicalLine scanLine();
    void step(LogicalLine& line);
    void stepCode(LogicalLine& line);
    void append(char c, size_t offset);
    bool expectsHeaderName() const;
    size_t continuationLength(size_t pos) const;
    char peek(size_t pos) const { return pos < mText.size() ? mText[pos] : '\0'; }

    std::string_view mText;
    size_t mPos = 0;
    uint32_t mLine = 0;
    Mode mMode = Mode::Code;
    size_t mCommentBegin = 0;          // the "/*" of the open block comment
    bool mTokenBeforeComment = false;  // a token preceded the open block comment on its line
    // State of the logical line being scanned.
    std::string mCode;             // comments as ' ', continuations removed
    std::vector<size_t> mOffsets;  // text offset of each mCode character
    bool mTokenSeen = false;       // a token precedes, on this line or before its open comment
    bool mIsDirective = false;
    char mHeaderClose = '"';
};

}  // namespace varc::includes
