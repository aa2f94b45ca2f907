// SPDX-License-Identifier: Apache-2.0
// Object-like macros a program text defines itself.
#include "varc/driver/UserDefines.h"

#include "varc/core/AsciiIdentifier.h"

namespace varc::driver {

namespace {

// A line's own blanks, and the '\n' that ends it.
bool isBlank(char c) { return isAsciiLineBlank(c) || c == '\n'; }

size_t skipBlanks(std::string_view line, size_t pos) {
    while (pos < line.size() && isBlank(line[pos])) ++pos;
    return pos;
}

// "NAME" and "replacement" of an object-like `#define` line; false for any other line.
bool parseDefine(std::string_view line, std::string_view& name, std::string_view& replacement) {
    size_t pos = skipBlanks(line, 0);
    if (pos >= line.size() || line[pos] != '#') return false;
    pos = skipBlanks(line, pos + 1);
    if (line.substr(pos, 6) != "define" || pos + 6 >= line.size() || !isBlank(line[pos + 6])) {
        return false;
    }
    pos = skipBlanks(line, pos + 6);
    size_t start = pos;
    while (pos < line.size() && isAsciiIdentifierChar(line[pos])) ++pos;
    if (pos == start || (pos < line.size() && line[pos] == '(')) return false;  // function-like
    name = line.substr(start, pos - start);
    replacement = line.substr(skipBlanks(line, pos));
    if (size_t comment = replacement.find("//"); comment != std::string_view::npos) {
        replacement = replacement.substr(0, comment);
    }
    while (!replacement.empty() && isBlank(replacement.back())) replacement.remove_suffix(1);
    // A continued or commented-out replacement is not one this simple reading can compare.
    return replacement.find('\\') == std::string_view::npos &&
           replacement.find("/*") == std::string_view::npos;
}

// Only the pass macros, and only definitions that say "this pass is defined": a text's
// `#ifndef SHADER_TARGET` / `#define SHADER_TARGET 25` fallback must not replace the real value.
bool isAdoptable(std::string_view name, std::string_view replacement) {
    return name.starts_with("UNITY_PASS_") && (replacement.empty() || replacement == "1");
}

template <typename Visit>
void forEachLine(std::string_view text, Visit&& visit) {
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        end = end == std::string_view::npos ? text.size() : end + 1;
        visit(text.substr(start, end - start));
        start = end;
    }
}

}  // namespace

UserDefines::UserDefines(std::string_view text) {
    forEachLine(text, [this](std::string_view line) {
        std::string_view name, replacement;
        if (parseDefine(line, name, replacement) && isAdoptable(name, replacement)) {
            mReplacements.emplace(std::string(name), std::string(replacement));
        }
    });
}

void UserDefines::adopt(std::vector<PredefinedMacro>& macros) const {
    for (PredefinedMacro& macro : macros) {
        if (macro.kind != PredefinedMacro::Kind::Define) continue;
        auto own = mReplacements.find(macro.name);
        if (own != mReplacements.end()) macro.value = own->second;
    }
}

}  // namespace varc::driver
