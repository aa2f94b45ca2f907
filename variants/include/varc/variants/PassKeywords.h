// SPDX-License-Identifier: Apache-2.0
// What a program block's pragmas declare: keyword sets, skips, filters, entry points, target.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "varc/core/SourceLocation.h"
#include "varc/core/Stage.h"

namespace varc::variants {

enum class DirectiveKind { MultiCompile, ShaderFeature, DynamicBranch };

// The stages a keyword set applies to (`_vertex`, `_fragment`, ... suffixes): a StageMask of the
// program stages, plus kRaytracingStages for `_raytracing` (ray-tracing shaders, which a
// rasterisation pass never compiles). A set without a suffix applies to kEverySetStage.
inline constexpr StageMask kRaytracingStages = StageMask{1} << kStageCount;
inline constexpr StageMask kEverySetStage = kAllStages | kRaytracingStages;

// One `#pragma multi_compile...` line (or one set produced by a shortcut).
struct KeywordSetDecl {
    DirectiveKind kind = DirectiveKind::MultiCompile;
    bool local = false;                 // `_local` form
    StageMask stages = kEverySetStage;  // see kEverySetStage
    std::vector<std::string> keywords;  // declared order; "" is the no-keyword entry (`_`, `__`)
    std::string directive;              // as written: "multi_compile_local_fragment",
                                        // "multi_compile_fwdadd" for shortcut sets
    SourceLocation location;            // of the pragma line
};

// A built-in validity rule of a shortcut: a variant with |keyword| on is kept only if at least
// one of |requiresAnyOf| is on (when non-empty) and none of |forbids| is on.
// Example (fwdadd_fullshadows): SHADOWS_DEPTH requires SPOT.
struct ValidityRule {
    std::string keyword;
    std::vector<std::string> requiresAnyOf;
    std::vector<std::string> forbids;
    std::string origin;  // shortcut that introduced it, for reports
};

// Everything the keyword model reads from one pass's pragmas.
struct PassKeywords {
    std::vector<KeywordSetDecl> sets;          // variant-producing sets in declaration order
    std::vector<KeywordSetDecl> dynamicBranches;  // recorded, produce no variants
    std::vector<std::string> skipped;          // skip_variants keywords (any position)
    std::vector<ValidityRule> rules;           // from shortcuts
    std::string vertexEntry, fragmentEntry;    // #pragma vertex / fragment
    std::string geometryEntry, hullEntry, domainEntry;
    std::string target;                        // #pragma target ("3.0"), "" = default
    std::vector<std::string> excludeRenderers, onlyRenderers;
    std::vector<std::string> instancingOptions;
    std::vector<std::string> otherPragmas;     // recognised but unmodelled (e.g. "enable_d3d11_debug_symbols")
};

}  // namespace varc::variants
