// SPDX-License-Identifier: Apache-2.0
// Recognises include guards: `#pragma once` and the #ifndef/#define/#endif idiom.
#include "GuardDetector.h"

#include <optional>

namespace varc::includes {

namespace {

std::optional<size_t> firstNonBlank(const std::vector<LogicalLine>& lines, size_t from) {
    for (size_t i = from; i < lines.size(); ++i) {
        if (!lines[i].blank) return i;
    }
    return std::nullopt;
}

bool isDirective(const std::vector<LogicalLine>& lines, std::optional<size_t> index,
                 DirectiveKind kind) {
    return index && lines[*index].isDirective && lines[*index].directive.kind == kind;
}

// The #endif closing the conditional opened at |open|, or nullopt when the block has a
// top-level #else/#elif (so not all of it is guarded) or is never closed.
std::optional<size_t> matchingEndif(const std::vector<LogicalLine>& lines, size_t open) {
    int depth = 0;
    for (size_t i = open; i < lines.size(); ++i) {
        if (!lines[i].isDirective) continue;
        switch (lines[i].directive.kind) {
            case DirectiveKind::If:
            case DirectiveKind::Ifdef:
            case DirectiveKind::Ifndef:
                ++depth;
                break;
            case DirectiveKind::Else:
                if (depth == 1) return std::nullopt;
                break;
            case DirectiveKind::Endif:
                if (--depth == 0) return i;
                break;
            default:
                break;
        }
    }
    return std::nullopt;
}

}  // namespace

IncludeGuard detectIncludeGuard(const std::vector<LogicalLine>& lines) {
    IncludeGuard guard;
    std::optional<size_t> open = firstNonBlank(lines, 0);
    if (!open || !lines[*open].isDirective) return guard;
    const Directive& first = lines[*open].directive;
    if (first.kind == DirectiveKind::Pragma && first.argument == "once") {
        guard.kind = GuardKind::PragmaOnce;
        return guard;
    }
    bool opensGuard = first.kind == DirectiveKind::Ifndef || first.kind == DirectiveKind::If;
    if (!opensGuard || first.argument.empty()) return guard;
    std::optional<size_t> define = firstNonBlank(lines, *open + 1);
    if (!isDirective(lines, define, DirectiveKind::Define) ||
        lines[*define].directive.argument != first.argument) {
        return guard;
    }
    std::optional<size_t> close = matchingEndif(lines, *open);
    if (!close || firstNonBlank(lines, *close + 1)) return guard;
    guard = {GuardKind::Macro, first.argument, *open, *close};
    return guard;
}

}  // namespace varc::includes
