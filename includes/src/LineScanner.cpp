// SPDX-License-Identifier: Apache-2.0
// Splits source text into logical lines, telling directives from comments and strings.
#include "LineScanner.h"

#include "GuardDetector.h"

namespace varc::includes {

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\f' || c == '\v' || c == '\r'; }

// Offsets where physical lines start; same convention as SourceMap ("a\n" is one line).
std::vector<size_t> indexLines(std::string_view text) {
    std::vector<size_t> starts;
    if (text.empty()) return starts;
    starts.push_back(0);
    for (size_t i = 0; i + 1 < text.size(); ++i) {
        if (text[i] == '\n') starts.push_back(i + 1);
    }
    return starts;
}

// True when |code| is `#include` or `#include_with_pragmas` plus blanks: a '"' or '<' now
// opens a header name, read literally up to its closing character.
bool isIncludePrefix(std::string_view code) {
    size_t i = 0;
    while (i < code.size() && isSpace(code[i])) ++i;
    if (i >= code.size() || code[i] != '#') return false;
    ++i;
    while (i < code.size() && isSpace(code[i])) ++i;
    size_t end = code.size();
    while (end > i && isSpace(code[end - 1])) --end;
    std::string_view keyword = code.substr(i, end - i);
    return keyword == "include" || keyword == "include_with_pragmas";
}

}  // namespace

ScannedFile LineScanner::scan(std::string_view text) {
    LineScanner scanner(text);
    ScannedFile file;
    file.text = text;
    file.lineStarts = indexLines(text);
    while (scanner.mPos < text.size()) file.lines.push_back(scanner.scanLine());
    if (scanner.mMode == Mode::BlockComment) file.unterminatedComment = scanner.mCommentBegin;
    file.guard = detectIncludeGuard(file.lines);
    return file;
}

// Length of a backslash-newline at |pos| ("\\\n" or "\\\r\n"), or 0.
size_t LineScanner::continuationLength(size_t pos) const {
    if (peek(pos) != '\\') return 0;
    if (peek(pos + 1) == '\n') return 2;
    if (peek(pos + 1) == '\r' && peek(pos + 2) == '\n') return 3;
    return 0;
}

LogicalLine LineScanner::scanLine() {
    LogicalLine line;
    line.firstLine = mLine;
    line.startsInComment = mMode == Mode::BlockComment;
    mCode.clear();
    mOffsets.clear();
    mTokenSeen = line.startsInComment && mTokenBeforeComment;
    mIsDirective = false;
    while (mPos < mText.size() && mText[mPos] != '\n') {
        if (size_t length = continuationLength(mPos)) {
            mPos += length;
            // A backslash-newline that ends the text joins no further line (found by the
            // include fuzzer: counting one made lastLine point past the last line).
            if (mPos < mText.size()) ++mLine;
            continue;
        }
        step(line);
    }
    if (mPos < mText.size()) ++mPos;  // the '\n'
    line.lastLine = mLine++;
    if (mMode != Mode::BlockComment) mMode = Mode::Code;  // strings and // end with the line
    line.endsInComment = mMode == Mode::BlockComment;
    if (line.endsInComment) mTokenBeforeComment = mTokenSeen;
    if (mIsDirective) {
        line.isDirective = true;
        line.directive = parseDirective(mCode, mOffsets);
    }
    return line;
}

// Consumes one character (two for comment delimiters) in the current mode.
void LineScanner::step(LogicalLine& line) {
    char c = mText[mPos];
    switch (mMode) {
        case Mode::BlockComment:
            if (c == '*' && peek(mPos + 1) == '/') {
                mMode = Mode::Code;
                mPos += 2;
                if (line.startsInComment && line.commentTailEnd == 0) line.commentTailEnd = mPos;
            } else {
                ++mPos;
            }
            return;
        case Mode::LineComment:
            ++mPos;
            return;
        case Mode::String:
            append(c, mPos++);
            if (c == '\\' && mPos < mText.size() && mText[mPos] != '\n') {
                append(mText[mPos], mPos);
                ++mPos;
            } else if (c == '"') {
                mMode = Mode::Code;
            }
            return;
        case Mode::HeaderName:
            append(c, mPos++);
            if (c == mHeaderClose) mMode = Mode::Code;
            return;
        case Mode::Code:
            stepCode(line);
            return;
    }
}

void LineScanner::stepCode(LogicalLine& line) {
    char c = mText[mPos];
    char next = peek(mPos + 1);
    if (c == '/' && (next == '/' || next == '*')) {
        append(' ', mPos);
        mMode = next == '/' ? Mode::LineComment : Mode::BlockComment;
        if (next == '*') line.openCommentBegin = mCommentBegin = mPos;
        mPos += 2;
        return;
    }
    if (!isSpace(c)) {
        if (!mTokenSeen && c == '#') mIsDirective = true;
        mTokenSeen = true;
        line.blank = false;
        if ((c == '"' || c == '<') && mIsDirective && expectsHeaderName()) {
            mMode = Mode::HeaderName;
            mHeaderClose = c == '"' ? '"' : '>';
        } else if (c == '"') {
            mMode = Mode::String;
        }
    }
    if (c == '\r' && next == '\n') {
        ++mPos;  // the CR of a CRLF line end is not code
        return;
    }
    append(c, mPos++);
}

void LineScanner::append(char c, size_t offset) {
    mCode.push_back(c);
    mOffsets.push_back(offset);
}

bool LineScanner::expectsHeaderName() const { return isIncludePrefix(mCode); }

}  // namespace varc::includes
