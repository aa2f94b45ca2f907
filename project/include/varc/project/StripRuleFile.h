// SPDX-License-Identifier: Apache-2.0
// The user's strip rules, read from a small declarative YAML file into plain data.
//
// The file is varc's counterpart of Unity's scriptable stripping (IPreprocessShaders): each rule
// removes the variants that match it. Format:
//
//   # varc strip rules: each rule removes the variants that match it
//   rules:
//     - name: no exp2 fog in add passes  # required, unique within the file
//       shader: "Custom/*"               # optional: shader-name glob (* = any run); default all
//       pass: ForwardAdd                 # optional: pass name or LightMode; default every pass
//       stage: fragment                  # optional: vertex|fragment|geometry|hull|domain
//       with: [FOG_EXP2]                 # keywords that must all be on
//       without: LIGHTMAP_ON             # keywords that must all be off (one keyword: a scalar)
//
// * The top level is a mapping whose only key is `rules:`, a sequence; `rules: []` means no rules.
// * A rule is a mapping with the keys above and no others; a key written twice is an error.
// * `with` and `without` are each a keyword or a sequence of keywords. A keyword is an
//   identifier: ASCII letters, digits and `_`, not starting with a digit. At least one of them
//   must name a keyword: a rule matching on no keyword would remove every variant.
// * A key with no value (`shader:`) counts as not written.
// * A keyword in both `with` and `without` is a warning: the rule can never match.
//
// The rules' meaning (globs, pass names, stages) is variants::StripRule's; this library only
// reads them, so it does not depend on `variants`.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "varc/core/Diagnostic.h"
#include "varc/core/SourceLocation.h"
#include "varc/core/Stage.h"

namespace varc::project {

// One rule of a strip-rule file, as written (see the file comment for each field's meaning).
struct StripRuleSpec {
    std::string name;
    SourceLocation location;  // the rule's mapping: its first key, just after the `- `
    std::string shader;       // "" = every shader
    std::string pass;         // "" = every pass
    std::optional<Stage> stage;
    std::vector<std::string> with;     // in written order
    std::vector<std::string> without;  // in written order
};

// Reads the strip rules of |file| (format above), in written order. Every problem is reported
// to |sink| as an error at the offending node (1-based line and column; line 0 for the file as a
// whole, e.g. it cannot be read): malformed YAML, a wrong top level, a rule that is not a mapping,
// an unknown or repeated key, a missing, empty or duplicate name (with a note at the first use),
// a value of the wrong type, an unknown stage, a keyword that is not an identifier, a rule with
// neither `with` nor `without`. Reading goes on after an error so that one run reports them all.
// |fileIdFor| gives the FileId of |file| for diagnostics and StripRuleSpec::location (e.g. it
// registers the file in the caller's SourceMap, as LoadOptions::fileIdFor); empty: FileId 0.
// Returns nullopt when an error was reported (warnings do not count). Never throws.
// Example: `rules:\n  - name: x\n    with: FOG_EXP2\n` -> one rule, name "x", location 2:5
// (the `n` of `name`), with {"FOG_EXP2"}.
std::optional<std::vector<StripRuleSpec>> readStripRules(
    const std::filesystem::path& file, DiagnosticSink& sink,
    const std::function<FileId(const std::filesystem::path&)>& fileIdFor);

}  // namespace varc::project
