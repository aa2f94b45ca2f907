// SPDX-License-Identifier: Apache-2.0
// Calls of one-parameter macros with an empty argument, expanded in place.
#include "varc/frontend/EmptyMacroArguments.h"

#include <map>
#include <optional>
#include <vector>

#include "varc/core/AsciiIdentifier.h"

namespace varc::frontend {

namespace {

struct Definition {
    size_t offset = 0;    // of the '#'
    std::string body;     // without the parameter, one line
    bool usable = false;  // false: the body pastes or stringises something else
};

size_t skipBlanks(std::string_view text, size_t i) {
    while (i < text.size() && (text[i] == ' ' || text[i] == '\t')) ++i;
    return i;
}

size_t identifierEnd(std::string_view text, size_t i) {
    while (i < text.size() && isAsciiIdentifierChar(text[i])) ++i;
    return i;
}

// |body| without |parameter| and the `##` next to it; nullopt when something else is pasted
// or stringised. "float _A##id;" with "id" -> " float _A;".
std::optional<std::string> bodyWithoutParameter(std::string_view body, std::string_view parameter) {
    std::string out;
    size_t i = 0;
    while (i < body.size()) {
        if (isAsciiIdentifierChar(body[i]) && (i == 0 || !isAsciiIdentifierChar(body[i - 1]))) {
            size_t end = identifierEnd(body, i);
            if (body.substr(i, end - i) != parameter) {
                out.append(body.substr(i, end - i));
                i = end;
                continue;
            }
            // Drop a `##` after the parameter (one before it was skipped below).
            i = skipBlanks(body, end);
            if (body.compare(i, 2, "##") == 0) i = skipBlanks(body, i + 2);
            continue;
        }
        if (body[i] == '#') {
            size_t next = skipBlanks(body, i + 2);
            bool pastesParameter = body.compare(i, 2, "##") == 0 &&
                                   body.substr(next, identifierEnd(body, next) - next) == parameter;
            if (!pastesParameter) return std::nullopt;
            while (!out.empty() && (out.back() == ' ' || out.back() == '\t')) out.pop_back();
            i = next;
            continue;
        }
        out += body[i++];
    }
    return out;
}

// The one-parameter macros defined in |text|, by name, in order.
std::map<std::string, std::vector<Definition>, std::less<>> oneParameterMacros(
    std::string_view text) {
    std::map<std::string, std::vector<Definition>, std::less<>> macros;
    size_t line = 0;
    while (line < text.size()) {
        size_t hash = skipBlanks(text, line);
        size_t directive = skipBlanks(text, hash + 1);
        size_t logicalEnd = line;
        while (true) {  // the end of the line, continuations included
            logicalEnd = text.find('\n', logicalEnd);
            if (logicalEnd == std::string_view::npos) logicalEnd = text.size();
            size_t last = logicalEnd > 0 && text[logicalEnd - 1] == '\r' ? logicalEnd - 2
                                                                          : logicalEnd - 1;
            if (logicalEnd == text.size() || logicalEnd == 0 || text[last] != '\\') break;
            ++logicalEnd;
        }
        if (hash < text.size() && text[hash] == '#' && text.compare(directive, 6, "define") == 0) {
            size_t name = skipBlanks(text, directive + 6);
            size_t nameEnd = identifierEnd(text, name);
            size_t parameter = skipBlanks(text, nameEnd + 1);
            size_t parameterEnd = identifierEnd(text, parameter);
            size_t close = skipBlanks(text, parameterEnd);
            if (nameEnd > name && nameEnd < text.size() && text[nameEnd] == '(' &&
                parameterEnd > parameter && close < text.size() && text[close] == ')') {
                std::string body;
                for (char c : text.substr(close + 1, logicalEnd - close - 1)) {
                    if (c != '\\' && c != '\n' && c != '\r') body += c;
                }
                auto cleaned =
                    bodyWithoutParameter(body, text.substr(parameter, parameterEnd - parameter));
                std::string key(text.substr(name, nameEnd - name));
                macros[key].push_back({hash, cleaned.value_or(""), cleaned.has_value()});
            }
        }
        line = logicalEnd + 1;
    }
    return macros;
}

// The end of a call `(` [##] `)` whose '(' may follow blanks at |i|, or npos.
size_t emptyCallEnd(std::string_view text, size_t i) {
    i = skipBlanks(text, i);
    if (i >= text.size() || text[i] != '(') return std::string_view::npos;
    i = skipBlanks(text, i + 1);
    if (text.compare(i, 2, "##") == 0) i = skipBlanks(text, i + 2);
    return i < text.size() && text[i] == ')' ? i + 1 : std::string_view::npos;
}

}  // namespace

std::string expandEmptyMacroArguments(std::string_view text) {
    auto macros = oneParameterMacros(text);
    if (macros.empty()) return std::string(text);
    std::string out;
    size_t i = 0;
    while (i < text.size()) {
        if (!isAsciiIdentifierChar(text[i]) || (i > 0 && isAsciiIdentifierChar(text[i - 1]))) {
            out += text[i++];
            continue;
        }
        size_t end = identifierEnd(text, i);
        // An empty call is rare and cheap to see: look the name up only then.
        size_t callEnd = emptyCallEnd(text, end);
        const Definition* definition = nullptr;
        if (callEnd != std::string_view::npos) {
            auto macro = macros.find(text.substr(i, end - i));
            if (macro != macros.end()) {
                for (const Definition& candidate : macro->second) {
                    if (candidate.offset < i) definition = &candidate;
                }
            }
        }
        if (!definition || !definition->usable) {
            out.append(text.substr(i, end - i));
            i = end;
            continue;
        }
        out += definition->body;
        i = callEnd;
    }
    return out;
}

}  // namespace varc::frontend
