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
//  * errors: keyword repeated in a set, a repeated set, unknown multi_compile_* shortcut
//    (with a did-you-mean), unknown shortcut option, malformed names;
//  * shortcuts (multi_compile_fwdadd, ...) expand to sets plus ValidityRules, honouring options
//    (nolightmap, novertexlight, noshadow, ...);
//  * unknown non-keyword pragmas are kept in otherPragmas (Unity passes them to the compiler).
// Returns nullopt after reporting at least one error. Columns point at the offending token.
std::optional<PassKeywords> parsePragmas(const std::vector<PragmaLine>& pragmas,
                                         DiagnosticSink& sink);

}  // namespace varc::variants
