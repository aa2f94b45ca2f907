// SPDX-License-Identifier: Apache-2.0
// Maps each physical line of a preprocessed program to the (source, line) its #lines give it.
#include "pruner/LineOriginMap.h"

#include <optional>

namespace varc::frontend::pruner {
namespace {

struct LineDirective {
    uint64_t line = 0;
    std::string_view source;  // empty when absent
};

std::string_view skipBlanks(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    return s;
}

// Splits the next run of characters up to a blank, or a whole "quoted string", off |s|.
std::string_view takeWord(std::string_view& s) {
    s = skipBlanks(s);
    size_t n = 0;
    if (!s.empty() && s.front() == '"') {
        const size_t close = s.find('"', 1);
        n = close == std::string_view::npos ? s.size() : close + 1;
    }
    while (n < s.size() && s[n] != ' ' && s[n] != '\t') ++n;
    const std::string_view word = s.substr(0, n);
    s.remove_prefix(n);
    return word;
}

std::optional<uint64_t> parseNumber(std::string_view s) {
    if (s.empty() || s.size() > 9) return std::nullopt;
    uint64_t value = 0;
    for (const char c : s) {
        if (c < '0' || c > '9') return std::nullopt;
        value = value * 10 + static_cast<uint64_t>(c - '0');
    }
    return value;
}

bool isSource(std::string_view s) {
    if (s.size() >= 2 && s.front() == '"' && s.back() == '"') return true;
    return parseNumber(s).has_value();
}

// Parses "#line N" / "#line N M" / `#line N "file"`; a trailing `//` comment is allowed.
// Example: "#line 12 3" gives {12, "3"}; "#line x" gives nullopt.
std::optional<LineDirective> parseLineDirective(std::string_view text) {
    std::string_view rest = skipBlanks(text.substr(1));  // after '#'
    rest.remove_prefix(4);                               // "line", checked by the caller
    if (const size_t comment = rest.find("//");
        comment != std::string_view::npos && rest.find('"') == std::string_view::npos) {
        rest = rest.substr(0, comment);
    }
    const std::optional<uint64_t> line = parseNumber(takeWord(rest));
    const std::string_view source = takeWord(rest);
    if (!line || !takeWord(rest).empty() || (!source.empty() && !isSource(source))) {
        return std::nullopt;
    }
    return LineDirective{*line, source};
}

}  // namespace

bool LineOriginMap::isLineDirective(std::string_view text) {
    const std::string_view rest = skipBlanks(text.substr(1));
    return rest.substr(0, 4) == "line" && (rest.size() == 4 || rest[4] == ' ' || rest[4] == '\t');
}

bool LineOriginMap::build(const std::vector<DirectiveLine>& directives, size_t lineCount) {
    mOrigins.assign(lineCount, LineOrigin{});
    LineOrigin current;  // origin of the line being visited
    current.line = 1;
    size_t next = 0;
    for (size_t line = 0; line < lineCount; ++line) {
        mOrigins[line] = current;
        ++current.line;
        if (next < directives.size() && directives[next].line == line) {
            const DirectiveLine& directive = directives[next++];
            if (!isLineDirective(directive.text)) continue;
            const std::optional<LineDirective> parsed = parseLineDirective(directive.text);
            if (!parsed) return false;
            current.afterLineDirective = true;
            current.line = parsed->line;
            if (!parsed->source.empty()) {
                current.hasSource = true;
                current.source = parsed->source;
            }
        }
    }
    return true;
}

}  // namespace varc::frontend::pruner
