// SPDX-License-Identifier: Apache-2.0
// The variants one pass ships when a Unity project chooses them (`--project`), with the count
// after each stage of Unity's pipeline (docs/PROJECTS.md).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "varc/variants/MaterialSelection.h"
#include "varc/variants/StripRules.h"
#include "varc/variants/VariantKey.h"

namespace varc::frontend {

struct LoadedShader;
struct LoadedPass;

// Unity's staged counts, per pass: declared (after skip_variants and the shortcuts' rules) ->
// after materials and variant collections -> after Graphics Settings stripping -> after the
// user's strip rules, which is what ships.
struct VariantStageCounts {
    uint64_t declared = 0;
    uint64_t materials = 0;
    uint64_t settings = 0;
    uint64_t rules = 0;
};

struct VariantPlan {
    std::shared_ptr<const variants::MaterialSelection> selection;  // for explain
    VariantStageCounts counts;
    // False when more than the limit survive the materials stage: nothing was enumerated, the
    // later stages were not applied (settings and rules then equal materials) and the pass is
    // refused by checkVariantLimit.
    bool enumerated = false;
    std::vector<variants::VariantKey> keys;  // what ships, in enumeration order
    std::vector<uint64_t> settingsRemoved;   // per settings rule given (0: not applicable)
    std::vector<uint64_t> rulesRemoved;      // per user rule given (0: not applicable)
    // The rules as this pass reads them, with their names, for explainVariant.
    std::vector<variants::PassStripRule> settingsRules, userRules;
    std::vector<std::string> settingsRuleNames, userRuleNames;
};

// Why |key| (in the pass's keyword table) ships or not, naming the material, collection, setting
// or strip rule: "ships: enabled by material 'Assets/Rock.mat'", "left out: no material enables
// _DETAIL", "removed by Graphics Settings (fog stripping: FOG_EXP2 not kept)", "removed by strip
// rule 'no detail'". |ships| is set accordingly.
std::string explainVariant(const VariantPlan& plan, const variants::VariantKey& key, bool& ships);

// What a project asks of one shader: the keyword lists of the materials (and collection
// entries) that use it, whether Graphics Settings always include it, and the stripping rules.
struct ShaderDemand {
    std::vector<variants::KeywordRequest> requests;  // materials: every pass
    // ShaderVariantCollection entries: only the passes whose LightMode is that PassType.
    struct CollectionRequest {
        int passType = 0;  // Unity's PassType (passTypeOfLightMode)
        variants::KeywordRequest request;
    };
    std::vector<CollectionRequest> collectionRequests;
    bool alwaysIncluded = false;
    std::vector<variants::StripRule> settingsRules;  // from Graphics Settings
};

// Unity's PassType of a pass with LightMode |lightMode| (ignoring case): "" and Always 0 (Normal),
// Vertex 1, VertexLM 2, ForwardBase 4, ForwardAdd 5, PrepassBase 6, PrepassFinal 7,
// ShadowCaster 8, Deferred 10, Meta 11, MotionVectors 12; any other 13
// (ScriptableRenderPipeline).
int passTypeOfLightMode(std::string_view lightMode);

// Plans |pass| of |shader| for |demand| and the user's |rules| (in order; each rule's scope is
// checked here). Never enumerates the declared space; enumerates the selected variants only
// when there are at most |limit|.
VariantPlan planPass(const LoadedShader& shader, const LoadedPass& pass,
                     const ShaderDemand& demand, const std::vector<variants::StripRule>& rules,
                     uint64_t limit);

}  // namespace varc::frontend
