// SPDX-License-Identifier: Apache-2.0
#include "varc/driver/ObservedDefines.h"

#include <algorithm>

namespace varc::driver {

namespace {

bool isIdentifierStart(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}

bool isIdentifierChar(char c) { return isIdentifierStart(c) || (c >= '0' && c <= '9'); }

size_t skipBlanks(std::string_view text, size_t i) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    return i;
}

size_t identifierEnd(std::string_view text, size_t i) {
    while (i < text.size() && isIdentifierChar(text[i])) ++i;
    return i;
}

// After `#define` (blanks allowed around '#'): the offset of the macro name, or npos.
size_t defineNameOffset(std::string_view line) {
    size_t i = skipBlanks(line, 0);
    if (i >= line.size() || line[i] != '#') return std::string_view::npos;
    i = skipBlanks(line, i + 1);
    constexpr std::string_view kDefine = "define";
    if (line.substr(i, kDefine.size()) != kDefine) return std::string_view::npos;
    i = skipBlanks(line, i + kDefine.size());
    return i < line.size() && isIdentifierStart(line[i]) ? i : std::string_view::npos;
}

// The macro name of a `#define NAME...` line, or "" for other lines.
// Whether the directive at |hash| (a '#') is `#pragma`.
bool isPragma(std::string_view text, size_t hash) {
    constexpr std::string_view kPragma = "pragma";
    size_t i = skipBlanks(text, hash + 1);
    return text.substr(i, kPragma.size()) == kPragma &&
           (i + kPragma.size() >= text.size() || !isIdentifierChar(text[i + kPragma.size()]));
}

bool startsWith(std::string_view text, std::string_view prefix) {
    return text.substr(0, prefix.size()) == prefix;
}

bool endsWith(std::string_view text, std::string_view suffix) {
    return text.size() >= suffix.size() && text.substr(text.size() - suffix.size()) == suffix;
}

}  // namespace

ObservedNames::ObservedNames(std::string_view text) {
    size_t i = 0;
    bool lineStart = true;
    while (i < text.size()) {
        const char c = text[i];
        if (c == '\n') {
            lineStart = true;
            ++i;
            continue;
        }
        if (lineStart && c == '#' && isPragma(text, i)) {
            // glslang never macro-expands a #pragma line: keywords in `#pragma multi_compile`
            // are not observed by it.
            i = text.find('\n', i);
            if (i == std::string_view::npos) break;
            continue;
        }
        if (c != ' ' && c != '\t') lineStart = false;
        if (isIdentifierStart(text[i])) {
            size_t end = identifierEnd(text, i);
            mNames.emplace(text.substr(i, end - i));
            i = end;
        } else if (text[i] >= '0' && text[i] <= '9') {
            // A number with its suffix letters (1.0f, 0x1F) is one token, not an identifier.
            while (i < text.size() && (isIdentifierChar(text[i]) || text[i] == '.')) ++i;
        } else {
            ++i;
        }
    }
    // Token pasting happens in macro bodies: look at each logical line (joined at '\' newlines)
    // that holds a `##`.
    for (size_t start = 0; start < text.size() && !mObservesAll;) {
        size_t end = start;
        while (true) {
            end = text.find('\n', end);
            if (end == std::string_view::npos) {
                end = text.size();
                break;
            }
            size_t last = end;
            if (last > start && text[last - 1] == '\r') --last;
            if (last > start && text[last - 1] == '\\') {
                ++end;
                continue;
            }
            break;
        }
        std::string_view line = text.substr(start, end - start);
        if (line.find("##") != std::string_view::npos) addPastes(line);
        start = end + 1;
    }
}

void ObservedNames::addPastes(std::string_view directive) {
    std::vector<std::string_view> parameters;
    size_t body = 0;
    if (size_t name = defineNameOffset(directive); name != std::string_view::npos) {
        body = identifierEnd(directive, name);
        if (body < directive.size() && directive[body] == '(') {
            size_t close = directive.find(')', body);
            if (close == std::string_view::npos) {
                mObservesAll = true;
                return;
            }
            for (size_t i = body + 1; i < close;) {
                if (isIdentifierStart(directive[i])) {
                    size_t end = identifierEnd(directive, i);
                    parameters.push_back(directive.substr(i, end - i));
                    i = end;
                } else {
                    ++i;
                }
            }
            parameters.push_back("__VA_ARGS__");
            body = close + 1;
        }
    }
    auto isParameter = [&](std::string_view operand) {
        return operand.empty() ||
               std::find(parameters.begin(), parameters.end(), operand) != parameters.end();
    };
    // Walk the chains `A ## B ## ... ## Z`: only the two ends constrain the formed name.
    std::string_view text = directive.substr(body);
    for (size_t paste = text.find("##"); paste != std::string_view::npos;) {
        size_t leftEnd = paste;
        while (leftEnd > 0 && (text[leftEnd - 1] == ' ' || text[leftEnd - 1] == '\t')) --leftEnd;
        size_t leftStart = leftEnd;
        while (leftStart > 0 && isIdentifierChar(text[leftStart - 1])) --leftStart;
        std::string_view first = text.substr(leftStart, leftEnd - leftStart);
        std::string_view last;
        size_t next = paste;
        while (next != std::string_view::npos && text.compare(next, 2, "##") == 0) {
            size_t operand = skipBlanks(text, next + 2);
            size_t operandEnd = identifierEnd(text, operand);
            last = text.substr(operand, operandEnd - operand);
            next = skipBlanks(text, operandEnd);
            if (next >= text.size()) next = std::string_view::npos;
        }
        bool firstFree = isParameter(first), lastFree = isParameter(last);
        if (firstFree && lastFree) mPastesTokens = true;
        if (!firstFree) mPastedPrefixes.emplace_back(first);
        if (!lastFree) mPastedSuffixes.emplace_back(last);
        paste = next == std::string_view::npos ? next : text.find("##", next);
    }
}

bool ObservedNames::isPastedEnd(std::string_view name) const {
    return std::any_of(mPastedPrefixes.begin(), mPastedPrefixes.end(),
                       [&](const std::string& prefix) { return startsWith(name, prefix); }) ||
           std::any_of(mPastedSuffixes.begin(), mPastedSuffixes.end(),
                       [&](const std::string& suffix) { return endsWith(name, suffix); });
}

// Pasting joins whole tokens, and a joined token can be joined again: a name a free chain can
// form splits into at least two pieces, each a token of the text, a number (a pp-number starts
// with a digit; the preamble's values are numbers) or a name a literal-ended chain forms.
bool ObservedNames::isFormable(std::string_view name) const {
    {
        std::lock_guard<std::mutex> lock(mFormed->mutex);
        if (auto it = mFormed->answers.find(name); it != mFormed->answers.end()) return it->second;
    }
    auto isPiece = [&](std::string_view piece) {
        return (piece[0] >= '0' && piece[0] <= '9') || mNames.find(piece) != mNames.end() ||
               isPastedEnd(piece);
    };
    // splits[i]: name[0, i) splits into pieces.
    std::vector<bool> splits(name.size() + 1, false);
    splits[0] = true;
    for (size_t end = 1; end <= name.size(); ++end) {
        for (size_t begin = 0; begin < end && !splits[end]; ++begin) {
            if (!splits[begin] || (begin == 0 && end == name.size())) continue;
            splits[end] = isPiece(name.substr(begin, end - begin));
        }
    }
    const bool formable = splits[name.size()];
    std::lock_guard<std::mutex> lock(mFormed->mutex);
    mFormed->answers.emplace(std::string(name), formable);
    return formable;
}

bool ObservedNames::mayObserve(std::string_view name) const {
    if (mObservesAll || mNames.find(name) != mNames.end() || isPastedEnd(name)) return true;
    return mPastesTokens && isFormable(name);
}

bool ObservedNames::mayPaste(std::string_view name) const {
    return mObservesAll || isPastedEnd(name) || (mPastesTokens && isFormable(name));
}

void dropUnobservedMacros(std::vector<PredefinedMacro>& macros, const ObservedNames& names) {
    std::erase_if(macros, [&names](const PredefinedMacro& macro) {
        return macro.kind == PredefinedMacro::Kind::Define && !names.mayObserve(macro.identifier());
    });
}

}  // namespace varc::driver
