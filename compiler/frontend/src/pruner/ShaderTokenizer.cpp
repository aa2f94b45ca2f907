// SPDX-License-Identifier: Apache-2.0
// Splits preprocessed HLSL/GLSL into tokens, whole-line directives and comment-free line text.
#include "pruner/ShaderTokenizer.h"

#include <algorithm>

#include "varc/core/Trim.h"

namespace varc::frontend::pruner {
namespace {

constexpr size_t kNotFound = std::string::npos;

bool isIdentStart(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }

bool isDigit(char c) { return c >= '0' && c <= '9'; }

bool isIdentChar(char c) { return isIdentStart(c) || isDigit(c); }

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

}  // namespace

bool ShaderTokenizer::tokenize(std::string_view text) {
    mCode.assign(text);
    mLineStarts.assign(1, 0);
    for (size_t i = 0; i < mCode.size(); ++i) {
        if (mCode[i] == '\n' && i + 1 < mCode.size()) mLineStarts.push_back(i + 1);
    }
    mTokens.clear();
    mDirectives.clear();
    if (!blankCommentsAndDirectives()) return false;
    scanTokens();
    return true;
}

size_t ShaderTokenizer::lineEnd(size_t line) const {
    size_t end = line + 1 < mLineStarts.size() ? mLineStarts[line + 1] - 1 : mCode.size();
    if (end > mLineStarts[line] && mCode[end - 1] == '\n') --end;  // last line ending in '\n'
    return end;
}

// One pass over mCode: directives and comments become spaces, strings are skipped whole.
// A block comment does not end "line start", so `/* x */ #pragma p` is still a directive.
bool ShaderTokenizer::blankCommentsAndDirectives() {
    bool atLineStart = true;
    size_t i = 0;
    while (i < mCode.size()) {
        const char c = mCode[i];
        const char next = i + 1 < mCode.size() ? mCode[i + 1] : '\0';
        if (c == '\n') {
            atLineStart = true;
            ++i;
        } else if (isBlank(c)) {
            ++i;
        } else if (c == '/' && next == '/') {
            while (i < mCode.size() && mCode[i] != '\n') mCode[i++] = ' ';
        } else if (c == '/' && next == '*') {
            const size_t close = mCode.find("*/", i + 2);
            if (close == kNotFound) return false;
            for (; i < close + 2; ++i) {
                if (mCode[i] != '\n') mCode[i] = ' ';
            }
        } else if (c == '#' && atLineStart) {
            const size_t end = std::min(mCode.find('\n', i), mCode.size());
            recordDirective(i, end);
            i = end;
        } else {
            atLineStart = false;
            if (c == '"') {
                i = skipString(i);
                if (i == kNotFound) return false;
            } else {
                ++i;
            }
        }
    }
    return true;
}

// Returns the offset just past the string literal opening at |begin|, or npos if it does not
// close on its line.
size_t ShaderTokenizer::skipString(size_t begin) const {
    for (size_t i = begin + 1; i < mCode.size() && mCode[i] != '\n'; ++i) {
        if (mCode[i] == '\\') {
            ++i;
        } else if (mCode[i] == '"') {
            return i + 1;
        }
    }
    return kNotFound;
}

void ShaderTokenizer::recordDirective(size_t begin, size_t end) {
    const auto after = std::upper_bound(mLineStarts.begin(), mLineStarts.end(), begin);
    const auto line = static_cast<size_t>(after - mLineStarts.begin()) - 1;
    const std::string_view text = trim(std::string_view(mCode).substr(begin, end - begin));
    mDirectives.push_back({line, std::string(text)});
    for (size_t i = begin; i < end; ++i) mCode[i] = ' ';
}

void ShaderTokenizer::scanTokens() {
    size_t line = 0;
    size_t i = 0;
    const std::string_view code(mCode);
    while (i < code.size()) {
        const char c = code[i];
        if (c == '\n') {
            ++line;
            ++i;
            continue;
        }
        if (isBlank(c)) {
            ++i;
            continue;
        }
        size_t end = i + 1;
        TokenKind kind = TokenKind::Punct;
        if (isIdentStart(c)) {
            kind = TokenKind::Identifier;
            while (end < code.size() && isIdentChar(code[end])) ++end;
        } else if (isDigit(c) || (c == '.' && i + 1 < code.size() && isDigit(code[i + 1]))) {
            kind = TokenKind::Number;
            end = scanNumber(i);
        } else if (c == '"') {
            kind = TokenKind::String;
            end = skipString(i);  // cannot fail: checked by blankCommentsAndDirectives()
        }
        mTokens.push_back({kind, code.substr(i, end - i), line});
        i = end;
    }
}

// Numbers: digits, '.', letters for suffixes/hex, and a sign right after an exponent 'e'/'E'
// (`1e-5`, `2.5E+3f`). Hex literals never contain a sign, so `0x1e+1` reads as `0x1e` `+` `1`.
size_t ShaderTokenizer::scanNumber(size_t begin) const {
    const bool hex = mCode[begin] == '0' && begin + 1 < mCode.size() &&
                     (mCode[begin + 1] == 'x' || mCode[begin + 1] == 'X');
    size_t i = begin;
    while (i < mCode.size()) {
        const char c = mCode[i];
        const bool exponentSign =
            (c == '+' || c == '-') && !hex && (mCode[i - 1] == 'e' || mCode[i - 1] == 'E');
        if (!isIdentChar(c) && c != '.' && !exponentSign) break;
        ++i;
    }
    return i;
}

}  // namespace varc::frontend::pruner
