// SPDX-License-Identifier: Apache-2.0
// Rules that remove a pass's variants by their keywords: Graphics Settings' built-in stripping
// and the user's declarative counterpart of Unity's scriptable stripping.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "varc/core/SourceLocation.h"
#include "varc/core/Stage.h"
#include "varc/variants/PassKeywords.h"
#include "varc/variants/VariantKey.h"
#include "varc/variants/VariantSpace.h"

namespace varc::variants {

// Removes the variants of the passes it applies to that have every |with| keyword on and every
// |without| keyword off. Example: {with: {FOG_EXP2}, without: {LIGHTMAP_ON}}.
struct StripRule {
    std::string name;             // for reports: the user's name, or "fog: FOG_EXP2 not kept"
    SourceLocation location;      // where it was written (no file: made by varc)
    std::string shader;           // shader-name glob, `*` any run, case-sensitive ("" = all)
    std::string pass;             // pass name or LightMode, either case ("" = every pass)
    // With a stage, the rule reads only the keywords that stage sees (sets without a stage
    // suffix, or suffixed with it): a keyword of a `_fragment` set never matches `vertex`, as
    // stripping a vertex program by it would be a no-op in Unity.
    std::optional<Stage> stage;
    std::vector<std::string> with;
    std::vector<std::string> without;
};

// Whether |rule| applies to the pass |passName| / |lightMode| of shader |shaderName|.
bool stripRuleApplies(const StripRule& rule, std::string_view shaderName,
                      std::string_view passName, std::string_view lightMode);

// `*` matches any run of characters (also none); every other character matches itself.
bool globMatches(std::string_view pattern, std::string_view text);

// One rule as it reads a pass's keys: |never| when a |with| keyword is not declared (or not seen
// by the rule's stage), so the rule can remove nothing there.
struct PassStripRule {
    VariantKey with;
    VariantKey without;
    bool never = false;
};
PassStripRule compileStripRule(const StripRule& rule, const PassKeywords& keywords,
                               const KeywordTable& table);

// Removes from |keys| (order kept) each variant that one of |rules| matches; returns per rule how
// many it removed, a variant counting for the first rule that matches it.
std::vector<uint64_t> applyStripRules(const std::vector<PassStripRule>& rules,
                                      std::vector<VariantKey>& keys);

}  // namespace varc::variants
