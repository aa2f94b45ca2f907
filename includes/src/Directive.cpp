// SPDX-License-Identifier: Apache-2.0
// Classifies preprocessor directive lines for include splicing, guards and pragmas.
#include "Directive.h"

#include "varc/core/Check.h"
#include "varc/core/Trim.h"

namespace varc::includes {

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\f' || c == '\v' || c == '\r'; }

bool isIdentifierChar(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

size_t skipSpace(std::string_view code, size_t i) {
    while (i < code.size() && isSpace(code[i])) ++i;
    return i;
}

size_t skipIdentifier(std::string_view code, size_t i) {
    while (i < code.size() && isIdentifierChar(code[i])) ++i;
    return i;
}

// The blanks isSpace() accepts (no line break).
constexpr std::string_view kBlanks = " \t\f\v\r";

// The identifier at |i| after blanks, or "" when there is none.
std::string_view identifierAt(std::string_view code, size_t i) {
    i = skipSpace(code, i);
    return code.substr(i, skipIdentifier(code, i) - i);
}

// Text offset of |code[i]|. At the end of the line: just past the last non-blank character,
// so "#include   // x" points right after "include", not into the comment.
size_t offsetAt(std::string_view code, const std::vector<size_t>& offsets, size_t i) {
    if (i < code.size()) return offsets[i];
    size_t last = code.size();
    while (last > 0 && isSpace(code[last - 1])) --last;
    return last == 0 ? offsets.front() : offsets[last - 1] + 1;
}

// X when |condition| is exactly `!defined(X)` or `!defined X` (blanks allowed), else "".
std::string notDefinedMacro(std::string_view condition) {
    size_t i = skipSpace(condition, 0);
    if (i >= condition.size() || condition[i] != '!') return "";
    i = skipSpace(condition, i + 1);
    size_t end = skipIdentifier(condition, i);
    if (condition.substr(i, end - i) != "defined") return "";
    i = skipSpace(condition, end);
    bool parenthesized = i < condition.size() && condition[i] == '(';
    if (parenthesized) i = skipSpace(condition, i + 1);
    end = skipIdentifier(condition, i);
    std::string macro(condition.substr(i, end - i));
    i = skipSpace(condition, end);
    if (parenthesized) {
        if (i >= condition.size() || condition[i] != ')') return "";
        i = skipSpace(condition, i + 1);
    }
    return (macro.empty() || i != condition.size()) ? "" : macro;
}

void malformed(Directive& directive, size_t offset, std::string message) {
    directive.kind = DirectiveKind::MalformedInclude;
    directive.argumentOffset = offset;
    directive.error = std::move(message);
}

// Reads the `"name"` or `<name>` after an include keyword that ends at |i|.
void parseInclude(Directive& directive, std::string_view keyword, std::string_view code,
                  const std::vector<size_t>& offsets, size_t i) {
    directive.withPragmas = keyword == "include_with_pragmas";
    i = skipSpace(code, i);
    if (i >= code.size() || (code[i] != '"' && code[i] != '<')) {
        malformed(directive, offsetAt(code, offsets, i),
                  "expected \"FILENAME\" or <FILENAME> after #" + std::string(keyword));
        return;
    }
    char close = code[i] == '"' ? '"' : '>';
    size_t end = code.find(close, i + 1);
    if (end == std::string_view::npos) {
        malformed(
            directive, offsets[i],
            std::string("missing terminating ") + close + " character in #" + std::string(keyword));
        return;
    }
    if (end == i + 1) {
        malformed(directive, offsets[i], "empty filename in #" + std::string(keyword));
        return;
    }
    directive.kind = DirectiveKind::Include;
    directive.angled = close == '>';
    directive.argument = std::string(code.substr(i + 1, end - i - 1));
    directive.argumentOffset = offsets[i];
    size_t extra = skipSpace(code, end + 1);
    if (extra < code.size()) directive.extraTokensOffset = offsets[extra];
}

// Fills in the kind (and argument) for the non-include keywords.
void classify(Directive& directive, std::string_view keyword, std::string_view rest) {
    using K = DirectiveKind;
    if (keyword == "pragma") {
        directive.kind = K::Pragma;
        directive.argument = std::string(trim(rest, kBlanks));
    } else if (keyword == "if") {
        directive.kind = K::If;
        directive.argument = notDefinedMacro(rest);
    } else if (keyword == "ifdef") {
        directive.kind = K::Ifdef;
    } else if (keyword == "ifndef" || keyword == "define") {
        directive.kind = keyword == "ifndef" ? K::Ifndef : K::Define;
        directive.argument = std::string(identifierAt(rest, 0));
    } else if (keyword == "else" || keyword == "elif" || keyword == "elifdef" ||
               keyword == "elifndef") {
        directive.kind = K::Else;
    } else if (keyword == "endif") {
        directive.kind = K::Endif;
    }
}

}  // namespace

Directive parseDirective(std::string_view code, const std::vector<size_t>& offsets) {
    VARC_CHECK(code.size() == offsets.size()) << "code and offsets differ in length";
    size_t hash = skipSpace(code, 0);
    VARC_CHECK(hash < code.size() && code[hash] == '#') << "not a directive: " << code;
    Directive directive;
    directive.hashOffset = offsets[hash];
    size_t begin = skipSpace(code, hash + 1);
    size_t end = skipIdentifier(code, begin);
    std::string_view keyword = code.substr(begin, end - begin);
    if (keyword == "include" || keyword == "include_with_pragmas") {
        parseInclude(directive, keyword, code, offsets, end);
    } else {
        classify(directive, keyword, code.substr(end));
    }
    return directive;
}

}  // namespace varc::includes
