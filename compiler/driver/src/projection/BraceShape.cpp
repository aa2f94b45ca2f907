// SPDX-License-Identifier: Apache-2.0
// Brace balance of macros and conditional groups, for the reachable-code projection.
#include "BraceShape.h"

#include <algorithm>
#include <unordered_map>

namespace varc::driver::projection {

namespace {

// A run of braces: its net depth change and the lowest depth reached, relative to its start.
struct BraceRun {
    int net = 0;
    int lowest = 0;

    void add(std::string_view token) {
        if (token == "{") ++net;
        if (token == "}") lowest = std::min(lowest, --net);
    }
    bool balanced() const { return net == 0 && lowest >= 0; }
};

}  // namespace

std::unordered_set<std::string_view> unbalancedBraceMacros(const std::vector<PpLine>& lines) {
    std::unordered_set<std::string_view> unbalanced;
    std::unordered_map<std::string_view, std::vector<const PpLine*>> definitions;
    for (const PpLine& line : lines) {
        if (line.kind != PpLine::Kind::Define) continue;
        definitions[line.name].push_back(&line);
        BraceRun run;
        for (std::string_view token : line.tokens) run.add(token);
        if (!run.balanced()) unbalanced.insert(line.name);
    }
    // A balanced body that names an unbalanced macro expands to unbalanced braces too.
    for (bool changed = true; changed;) {
        changed = false;
        for (const auto& [name, defs] : definitions) {
            if (unbalanced.count(name)) continue;
            for (const PpLine* def : defs) {
                bool names = std::any_of(def->tokens.begin(), def->tokens.end(),
                                         [&](std::string_view t) { return unbalanced.count(t); });
                if (!names) continue;
                unbalanced.insert(name);
                changed = true;
                break;
            }
        }
    }
    return unbalanced;
}

void markCleanGroups(std::vector<PpLine>& lines,
                     const std::unordered_set<std::string_view>& braceMacros) {
    using Kind = PpLine::Kind;
    struct Open {
        size_t start;  // the group's #if line
        BraceRun branch;
        bool clean = true;
    };
    std::vector<Open> open;  // the groups enclosing the current line, innermost last
    for (size_t i = 0; i < lines.size(); ++i) {
        const PpLine& line = lines[i];
        switch (line.kind) {
            case Kind::If:
            case Kind::Ifdef:
            case Kind::Ifndef:
                open.push_back({i, {}, true});
                break;
            case Kind::Elif:
            case Kind::Else:
                if (open.empty()) return;
                open.back().clean = open.back().clean && open.back().branch.balanced();
                open.back().branch = {};
                break;
            case Kind::Endif: {
                if (open.empty()) return;
                Open group = open.back();
                open.pop_back();
                group.clean = group.clean && group.branch.balanced();
                lines[group.start].clean = group.clean;
                // A clean group adds no braces to the branch around it; any other taints it.
                if (!group.clean && !open.empty()) open.back().clean = false;
                break;
            }
            case Kind::Text:
                if (open.empty()) break;
                for (std::string_view token : line.code) {
                    open.back().branch.add(token);
                    if (braceMacros.count(token)) open.back().clean = false;
                }
                break;
            default:  // #define, #undef, #pragma, #include, #line, #error...: not clean
                if (!open.empty()) open.back().clean = false;
        }
    }
}

}  // namespace varc::driver::projection
