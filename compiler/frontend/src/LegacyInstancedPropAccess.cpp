// SPDX-License-Identifier: Apache-2.0
// Unity 5.6's one-argument UNITY_ACCESS_INSTANCED_PROP(name), given the 2017.3+ buffer argument.
#include "varc/frontend/LegacyInstancedPropAccess.h"

#include "varc/core/AsciiIdentifier.h"

namespace varc::frontend {

namespace {

constexpr std::string_view kMacro = "UNITY_ACCESS_INSTANCED_PROP";
constexpr std::string_view kBuffer = "UnityLegacyInstancedProps, ";

// Whether the call whose '(' is at |open| has one non-empty argument: no top-level comma
// before its balancing ')'. False for an unbalanced call.
bool singleArgument(std::string_view text, size_t open) {
    int depth = 0;
    bool any = false;
    for (size_t i = open; i < text.size(); ++i) {
        char c = text[i];
        if (c == '(' || c == '[' || c == '{') {
            ++depth;
        } else if (c == ')' || c == ']' || c == '}') {
            if (--depth == 0) return any;
        } else if (c == ',' && depth == 1) {
            return false;
        } else if (c != ' ' && c != '\t' && c != '\n' && c != '\r' && c != '\\') {
            any = true;
        }
    }
    return false;
}

}  // namespace

std::string expandLegacyInstancedPropAccess(std::string_view text) {
    std::string out;
    size_t copied = 0;
    for (size_t at = text.find(kMacro); at != std::string_view::npos;
         at = text.find(kMacro, at + kMacro.size())) {
        size_t end = at + kMacro.size();
        if ((at > 0 && isAsciiIdentifierChar(text[at - 1])) ||
            (end < text.size() && isAsciiIdentifierChar(text[end])))
            continue;
        size_t open = end;
        while (open < text.size() && (text[open] == ' ' || text[open] == '\t')) ++open;
        if (open >= text.size() || text[open] != '(' || !singleArgument(text, open)) continue;
        out.append(text.substr(copied, open + 1 - copied));
        out.append(kBuffer);
        copied = open + 1;
    }
    if (copied == 0) return std::string(text);
    out.append(text.substr(copied));
    return out;
}

}  // namespace varc::frontend
