// SPDX-License-Identifier: Apache-2.0
// Macro redefinitions as Unity's HLSL compilers take them.
#include "varc/frontend/MacroRedefinitions.h"

#include <algorithm>
#include <charconv>
#include <set>

#include "varc/core/AsciiIdentifier.h"

namespace varc::frontend {

namespace {

std::string_view skipBlanks(std::string_view text) {
    while (!text.empty() && isAsciiLineBlank(text.front())) text.remove_prefix(1);
    return text;
}

// The word after `#` + |keyword| on |line| ("#  define PI 3" with "define" -> "PI"), or "".
std::string_view directiveArgument(std::string_view line, std::string_view keyword) {
    line = skipBlanks(line);
    if (line.empty() || line.front() != '#') return {};
    line = skipBlanks(line.substr(1));
    if (!line.starts_with(keyword) || line.size() == keyword.size() ||
        !isAsciiLineBlank(line[keyword.size()])) {
        return {};
    }
    line = skipBlanks(line.substr(keyword.size()));
    size_t end = 0;
    while (end < line.size() && isAsciiIdentifierChar(line[end])) ++end;
    return line.substr(0, end);
}

}  // namespace

std::vector<std::string> redefinedMacros(std::string_view log) {
    constexpr std::string_view kMarker = "Macro redefined; different substitutions: ";
    std::vector<std::string> names;
    for (size_t at = log.find(kMarker); at != std::string_view::npos;
         at = log.find(kMarker, at + 1)) {
        std::string_view rest = log.substr(at + kMarker.size());
        size_t end = 0;
        while (end < rest.size() && isAsciiIdentifierChar(rest[end])) ++end;
        std::string name(rest.substr(0, end));
        if (!name.empty() && std::find(names.begin(), names.end(), name) == names.end()) {
            names.push_back(std::move(name));
        }
    }
    return names;
}

std::string undefineBeforeRedefinitions(std::string_view text,
                                        const std::vector<std::string>& names) {
    std::set<std::string, std::less<>> wanted(names.begin(), names.end()), seen;
    std::string result;
    result.reserve(text.size());
    std::string file = "0";
    long line = 1;  // the number of the next line, as the last #line directive set it
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        end = end == std::string_view::npos ? text.size() : end + 1;
        std::string_view physical = text.substr(start, end - start);
        std::string_view lineNumber = directiveArgument(physical, "line");
        if (!lineNumber.empty()) {
            std::string_view rest = skipBlanks(skipBlanks(physical).substr(1));
            rest = skipBlanks(rest.substr(4));
            rest = skipBlanks(rest.substr(lineNumber.size()));
            size_t fileEnd = 0;
            while (fileEnd < rest.size() && isAsciiIdentifierChar(rest[fileEnd])) ++fileEnd;
            std::from_chars(lineNumber.data(), lineNumber.data() + lineNumber.size(), line);
            if (fileEnd > 0) file = std::string(rest.substr(0, fileEnd));
            result.append(physical);
            start = end;
            continue;
        }
        std::string_view defined = directiveArgument(physical, "define");
        if (!defined.empty() && wanted.count(defined) && !seen.insert(std::string(defined)).second) {
            result += "#undef " + std::string(defined) + "\n#line " + std::to_string(line) + " " +
                      file + "\n";
        }
        result.append(physical);
        ++line;
        start = end;
    }
    return result;
}

}  // namespace varc::frontend
