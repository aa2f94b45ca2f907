// SPDX-License-Identifier: Apache-2.0
// Reads `#pragma` lines into PassKeywords, expanding Unity's multi_compile_* shortcuts.
#pragma once

#include <optional>
#include <vector>

#include "varc/core/Diagnostic.h"
#include "varc/core/PragmaLine.h"
#include "varc/variants/PassKeywords.h"

namespace varc::variants {

// Parses the pragmas of one program block (in source order). Rules (docs/KEYWORDS.md):
//  * multi_compile / shader_feature (+ _local, + stage suffixes), dynamic_branch(_local);
//  * all-underscore names are the no-keyword entry; `shader_feature X` means `_ X`;
//    `multi_compile X` is one always-on variant;
//  * errors: keyword repeated in a set, a repeated set (any order), a keyword declared by two
//    sets (note at the first), unknown multi_compile_* shortcut or shortcut option (with a
//    did-you-mean), malformed names, a directive without keywords;
//  * dynamic_branch wins over multi_compile/shader_feature for the same keyword (a warning);
//  * skip_variants may appear anywhere in the block;
//  * shortcuts (multi_compile_fwdadd, ...) expand to sets plus ValidityRules, honouring options
//    (nolightmap, novertexlight, noshadow, ...);
//  * unknown non-keyword pragmas are kept in otherPragmas (Unity passes them to the compiler).
// Returns nullopt after reporting at least one error. Columns point at the offending token
// (assuming `#pragma ` is spelled with one blank; PragmaLine keeps only the '#' column).
// Example: {"multi_compile _ A", "shader_feature B"} -> sets [{"", "A"}, {"", "B"}].
std::optional<PassKeywords> parsePragmas(const std::vector<PragmaLine>& pragmas,
                                         DiagnosticSink& sink);

}  // namespace varc::variants
