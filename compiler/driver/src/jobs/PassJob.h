// SPDX-License-Identifier: Apache-2.0
// Phase 1 of the compile driver: a pass being built (PassJob) and what turns one of its
// (variant, stage) items into a pruned stage source: the preamble of the defines its text can
// observe, glslang's preprocessing (shared by every item with the same preamble) and pruning to
// the stage's entry point.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "jobs/TextRewriteMemo.h"
#include "varc/core/Diagnostic.h"
#include "varc/core/Stage.h"
#include "varc/driver/KeywordProjection.h"
#include "varc/driver/ObservedDefines.h"
#include "varc/driver/ProgramCache.h"
#include "varc/driver/UserDefines.h"
#include "varc/frontend/ShaderLoader.h"
#include "varc/includes/SourceMap.h"
#include "varc/variants/VariantKey.h"

namespace varc::driver {
struct BuildOptions;
}

namespace varc::driver::detail {

// A pass being built: its variants and which stages it has (with their entry points).
struct PassJob {
    size_t shaderIndex = 0, passIndex = 0;
    const frontend::LoadedShader* shader = nullptr;
    const frontend::LoadedPass* pass = nullptr;
    std::vector<variants::VariantKey> keys;
    std::vector<std::pair<Stage, std::string>> stages;  // (stage, entry point)
    std::string text;  // the expanded source, in the front end's #line convention
    std::optional<ObservedNames> observed;   // the macro names |text| can see; none: keep all
    std::optional<UserDefines> userDefines;  // the macros |text| defines itself
    // Per stage: which keywords each variant's preprocessing looks up; empty: all are kept.
    std::vector<std::shared_ptr<KeywordProjection>> projections;
    // Per stage, with projections: the first stage whose preamble without keywords is the same
    // (stages that may share a preprocessing).
    std::vector<size_t> sameBaseAs;
    ProgramCacheKey textHash;  // of |text|, when a program cache is used
    // |text|'s variant-independent rewrites, shared by the job's variants (and its copies).
    std::shared_ptr<TextRewriteMemo> rewrites = std::make_shared<TextRewriteMemo>();
    // sourceIds[variant * stages.size() + stageIndex]
    std::vector<uint32_t> sourceIds;
};

// 128-bit content hash of a (preprocessing, stage, entry point): what an item's outcome depends on.
struct ItemKey {
    uint64_t low = 0, high = 0;
    bool operator==(const ItemKey&) const = default;
};

struct ItemKeyHash {
    size_t operator()(const ItemKey& key) const { return static_cast<size_t>(key.low); }
};

struct StageResult {
    bool ok = false;
    std::string text;
    std::vector<Diagnostic> diagnostics;
};

shaderlab::ProgramLanguage languageOf(const PassJob& job);

// Identifies variant |variant| of pass job |job| across the build (for counting variants).
uint64_t variantId(size_t job, size_t variant);

// "in the fragment stage of pass 1 (LightMode ForwardAdd) of shader "X", keywords: POINT".
std::string contextOf(const PassJob& job, Stage stage, size_t variant);

// The stages a pass compiles, from its #pragma vertex/fragment/...; reports missing entries.
bool collectStages(PassJob& job, DiagnosticSink& sink);

// Sets up |job|'s keyword projections (one per stage), after its stages and text are known.
// |reachableCode|: the stages are pruned to their entry points (BuildOptions::pruneStages) and
// their projections may leave out lookups in unreachable bodies (HLSL texts only).
void setUpProjections(PassJob& job, bool reachableCode);

// The preamble of one (variant, stage) without the defines the pass text cannot observe, nor
// the keywords its preprocessing does not look up in that variant.
std::string preambleOf(const PassJob& job, size_t variant, size_t stageIndex);

// What glslang's preprocessing of |job|'s text depends on besides the text: the preamble, and
// for GLSL the stage.
std::string preprocessKeyOf(const PassJob& job, Stage stage, std::string preamble);

ItemKey itemKeyOf(const std::string& preprocessKey, Stage stage, const std::string& entry);

StageResult preprocessStage(const PassJob& job, Stage stage, const std::string& entry,
                            const std::string& preamble, const includes::SourceMap& sourceMap);

// |preprocessed| cut to what |entry| reaches (unchanged without BuildOptions::pruneStages).
// |pruned|: false when the pruner could not parse it and returned it whole.
std::string pruneStage(const PassJob& job, const std::string& preprocessed,
                       const std::string& entry, const BuildOptions& options, bool& pruned);

}  // namespace varc::driver::detail
