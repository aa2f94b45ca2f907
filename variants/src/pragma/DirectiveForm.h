// SPDX-License-Identifier: Apache-2.0
// Decomposes keyword directive names: base, `_local`, stage suffix, or a shortcut name.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "varc/variants/PassKeywords.h"

namespace varc::variants {

enum class FormStatus {
    NotKeywordDirective,   // e.g. "vertex", "target", "multi_compilefoo"
    Set,                   // multi_compile / shader_feature / dynamic_branch (+ suffixes)
    Shortcut,              // multi_compile_<name> where <name> is not a suffix form
    UnknownSuffix,         // shader_feature_<x> / dynamic_branch_<x> with an unknown <x>
    StageOnDynamicBranch,  // dynamic_branch_vertex ...: Unity rejects stage suffixes there
};

struct DirectiveForm {
    FormStatus status = FormStatus::NotKeywordDirective;
    DirectiveKind kind = DirectiveKind::MultiCompile;
    bool local = false;
    StageMask stages = kEverySetStage;
    std::string_view shortcutName;  // Shortcut: "fwdadd" (views into the classified name)
};

// Suffixes are parsed first: base, then optional `_local`, then optional one stage suffix.
// Whatever else follows `multi_compile_` is a shortcut name (known or not).
// Examples: "multi_compile_local_fragment" -> Set{MultiCompile, local, stageBit(Stage::Fragment)};
//           "multi_compile_fwdadd" -> Shortcut{"fwdadd"}; "shader_feature_fwdadd" -> UnknownSuffix.
DirectiveForm classifyDirective(std::string_view name);

// Every valid non-shortcut spelling ("multi_compile", "shader_feature_local_vertex", ...), for
// did-you-mean suggestions.
std::vector<std::string> keywordDirectiveSpellings();

}  // namespace varc::variants
