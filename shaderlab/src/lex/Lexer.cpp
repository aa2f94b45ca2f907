// SPDX-License-Identifier: Apache-2.0
// Splits ShaderLab text into tokens and captures program blocks and attributes verbatim.
#include "lex/Lexer.h"

#include <string>

namespace varc::shaderlab {
namespace {

constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isIdentifierStart(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool isIdentifierChar(char c) { return isIdentifierStart(c) || isDigit(c); }
bool isSpace(char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

}  // namespace

Lexer::Lexer(std::string_view text, FileId file, DiagnosticSink& sink)
    : mText(text), mSink(sink), mLines(text, file) {
    // Files saved twice by tools that each add a mark start with several: all are skipped.
    while (mText.substr(mPos, kByteOrderMark.size()) == kByteOrderMark) {
        mPos += kByteOrderMark.size();
    }
}

Token Lexer::next() {
    if (mFailed) return make(TokenKind::Error, mPos, mPos, {});
    if (!skipTrivia()) return make(TokenKind::Error, mPos, mPos, {});
    if (mPos >= mText.size()) return make(TokenKind::EndOfFile, mPos, mPos, {});
    char c = mText[mPos];
    if (c == '"') return lexString();
    if (isIdentifierStart(c)) return lexWord(mPos);
    if (startsNumber()) return lexNumberOrWord();
    size_t begin = mPos++;
    return make(TokenKind::Symbol, begin, mPos, mText.substr(begin, 1));
}

bool Lexer::skipTrivia() {
    while (mPos < mText.size()) {
        char c = mText[mPos];
        if (isSpace(c)) {
            ++mPos;
        } else if (c == '/' && at(mPos + 1) == '/') {
            while (mPos < mText.size() && mText[mPos] != '\n') ++mPos;
        } else if (c == '/' && at(mPos + 1) == '*') {
            if (!skipBlockComment()) return false;
        } else if (c == '#' && mText.substr(mPos, 8) == "#warning") {
            skipWarningLine();
        } else {
            break;
        }
    }
    return true;
}

// Unity's shader upgrader writes `#warning Upgrade NOTE: ...` lines into .shader files, outside
// any program; Unity shows them and compiles the shader. varc reports them as warnings.
void Lexer::skipWarningLine() {
    size_t end = mText.find('\n', mPos);
    if (end == std::string_view::npos) end = mText.size();
    std::string_view message = mText.substr(mPos + 8, end - mPos - 8);
    while (!message.empty() && isSpace(message.front())) message.remove_prefix(1);
    while (!message.empty() && isSpace(message.back())) message.remove_suffix(1);
    mSink.warning(mLines.locationOf(mPos), "#warning " + std::string(message));
    mPos = end;
}

bool Lexer::skipBlockComment() {
    size_t close = mText.find("*/", mPos + 2);
    if (close == std::string_view::npos) {
        fail(mPos, "unterminated comment: missing '*/'");
        return false;
    }
    mPos = close + 2;
    return true;
}

Token Lexer::lexString() {
    size_t begin = mPos;
    size_t pos = begin + 1;
    while (pos < mText.size() && mText[pos] != '"' && mText[pos] != '\n') ++pos;
    if (pos >= mText.size() || mText[pos] != '"') {
        return fail(begin, "unterminated string: missing '\"' before the end of the line");
    }
    mPos = pos + 1;
    return make(TokenKind::String, begin, mPos, mText.substr(begin + 1, pos - begin - 1));
}

bool Lexer::startsNumber() const {
    size_t pos = mPos;
    if (at(pos) == '-' || at(pos) == '+') ++pos;
    return isDigit(at(pos)) || (at(pos) == '.' && isDigit(at(pos + 1)));
}

size_t Lexer::skipDigits(size_t pos) const {
    while (pos < mText.size() && isDigit(mText[pos])) ++pos;
    return pos;
}

// Numbers: [+-] digits [. digits] [e [+-] digits], or [+-] . digits [...]. A digit run directly
// followed by a letter is a word instead (`2D`, `2DArray`, `3D`).
Token Lexer::lexNumberOrWord() {
    size_t begin = mPos;
    size_t pos = begin;
    bool plainDigits = isDigit(at(pos));
    if (at(pos) == '-' || at(pos) == '+') ++pos;
    pos = skipDigits(pos);
    if (plainDigits && isIdentifierStart(at(pos)) && at(pos) != 'e' && at(pos) != 'E') {
        return lexWord(begin);
    }
    if (at(pos) == '.') pos = skipDigits(pos + 1);
    bool exponentSign = at(pos + 1) == '-' || at(pos + 1) == '+';
    if ((at(pos) == 'e' || at(pos) == 'E') && isDigit(at(pos + (exponentSign ? 2 : 1)))) {
        pos = skipDigits(pos + (exponentSign ? 2 : 1));
    } else if (plainDigits && pos == skipDigits(begin) && isIdentifierStart(at(pos))) {
        return lexWord(begin);  // "2Exx": digits then a word starting with e/E
    }
    mPos = pos;
    return make(TokenKind::Number, begin, pos, mText.substr(begin, pos - begin));
}

Token Lexer::lexWord(size_t begin) {
    size_t pos = begin;
    while (pos < mText.size() && isIdentifierChar(mText[pos])) ++pos;
    mPos = pos;
    return make(TokenKind::Identifier, begin, pos, mText.substr(begin, pos - begin));
}

std::optional<std::string_view> Lexer::captureUntilWord(const Token& opening,
                                                        std::string_view blockName,
                                                        std::string_view endWord) {
    if (mFailed) return std::nullopt;
    size_t begin = mPos;
    for (size_t pos = begin; pos + endWord.size() <= mText.size(); ++pos) {
        if (isWholeWordAt(pos, endWord)) {
            mPos = pos + endWord.size();
            return mText.substr(begin, pos - begin);
        }
    }
    fail(opening.begin,
         "unterminated " + std::string(blockName) + " block: missing " + std::string(endWord));
    return std::nullopt;
}

bool Lexer::isWholeWordAt(size_t pos, std::string_view word) const {
    if (!equalsIgnoreAsciiCase(mText.substr(pos, word.size()), word)) return false;
    if (pos > 0 && isIdentifierChar(mText[pos - 1])) return false;
    return !isIdentifierChar(at(pos + word.size()));
}

std::optional<std::string_view> Lexer::captureAttribute(const Token& opening) {
    if (mFailed) return std::nullopt;
    size_t begin = mPos;
    size_t pos = begin;
    while (pos < mText.size() && mText[pos] != ']' && mText[pos] != '\n') ++pos;
    if (pos >= mText.size() || mText[pos] != ']') {
        fail(opening.begin, "unterminated attribute: missing ']' before the end of the line");
        return std::nullopt;
    }
    mPos = pos + 1;
    return mText.substr(begin, pos - begin);
}

std::string_view Lexer::slice(size_t begin, size_t end) const {
    if (begin >= mText.size() || end <= begin) return {};
    return mText.substr(begin, end - begin);
}

Token Lexer::make(TokenKind kind, size_t begin, size_t end, std::string_view text) const {
    return Token{kind, text, mLines.locationOf(begin), begin, end};
}

Token Lexer::fail(size_t at, std::string message) {
    mSink.error(mLines.locationOf(at), std::move(message));
    mFailed = true;
    return make(TokenKind::Error, at, at, {});
}

}  // namespace varc::shaderlab
