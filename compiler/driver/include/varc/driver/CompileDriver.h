// SPDX-License-Identifier: Apache-2.0
// Compiles every variant of every loaded pass: each distinct stage program once, in parallel.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "varc/cache/CacheChain.h"
#include "varc/core/Diagnostic.h"
#include "varc/driver/OptimizerPool.h"
#include "varc/driver/ShardPlan.h"
#include "varc/driver/SpirvOptimizer.h"
#include "varc/frontend/ShaderLoader.h"
#include "varc/frontend/VariantLimit.h"
#include "varc/includes/SourceMap.h"
#include "varc/includes/SourcePathMap.h"
#include "varc/pack/PackModel.h"
#include "varc/variants/VariantKey.h"

namespace varc::driver {

using pack::kNoProgram;

struct BuildOptions {
    OptimizationLevel optimization = OptimizationLevel::Performance;
    unsigned jobs = 0;        // 0 = the machine's hardware concurrency
    bool keepGoing = false;   // compile everything even after errors, to report them all
    bool pruneStages = true;  // prune each stage to what its entry point reaches before dedup
    bool debugNames = false;  // keep OpName/OpMemberName/OpSource in the shipped SPIR-V
    // Drop the defines a pass's text cannot observe before preprocessing (ObservedDefines.h), so
    // variants differing only in them share one preprocessing. Off only to check that it
    // changes no program.
    bool shareUnobservedDefines = true;
    // Keep in each (variant, stage)'s preamble only the keywords its preprocessing looks up
    // (KeywordProjection.h): one preprocessing per distinct projection. Off only to check that
    // it changes no program.
    bool projectKeywords = true;
    // With the projection and pruning: leave out the lookups made only in the bodies of
    // functions a stage's entry point cannot reach (the pruner removes them whatever their
    // text). Off only to check that it changes no program.
    bool projectReachableCode = true;
    // Preprocess, prune and compile only this shard's share of the variants (ShardPlan.h: units
    // of whole variants, chosen before preprocessing); the other variants' stages name
    // placeholders (varc/pack/PartialPack.h) for `varc merge` to fill from the other parts.
    ShardSpec shard;
    // How the pack records source paths (relative to the project root, prefix maps).
    includes::SourcePathMap sourcePaths;
    // The program cache's levels (`--cache-dir`, `--cache`; a folder alone is
    // cache::CacheChain::open({cache::directoryCacheSpec(DIR)})): programs found there are not
    // compiled again, programs compiled are stored there. nullptr = no cache. BuildOutput reports
    // the levels' statistics; the driver adds their warnings to the diagnostics.
    std::shared_ptr<cache::CacheChain> cache;
    // Where SPIRV-Tools runs (validation before legalisation and the optimiser): in these worker
    // processes, so a crash or hang in it is an error for one program (and -O/-Os fall back to
    // legalisation alone with a warning); nullptr = in this process. `varc` sets it.
    std::shared_ptr<OptimizerPool> optimizerPool;
    // A pass with more variants is an error before anything is enumerated (VariantLimit.h).
    uint64_t maxVariantsPerPass = frontend::kDefaultMaxVariantsPerPass;
    // At most this many variants of each pass are built, spread evenly over its enumeration order
    // (variants::sampleEvenly): a quick check that every pass compiles, not a pack to ship; the
    // other variants are left out of the pack. 0 = every variant.
    uint64_t sampleVariantsPerPass = 0;
    // Keep the distinct pruned stage sources (BuildOutput::prunedSources) and which one each
    // variant's stage compiled (CompiledPass::variantSources), for `varc explain`.
    bool keepPrunedSources = false;
    // Called from worker threads after each distinct program compiles: (done, total). Must be
    // thread-safe; may be empty.
    std::function<void(size_t, size_t)> progress;
};

// Per pass: the staged counts of `varc build`'s summary.
struct PassBuildStats {
    uint64_t declaredVariants = 0;                      // full product of the keyword sets
    uint64_t variants = 0;                              // after skip_variants and shortcut rules
    std::array<size_t, kStageCount> distinctSources{};  // after preprocessing + pruning
    std::array<size_t, kStageCount> distinctModules{};  // after compiling, by SPIR-V bytes
};

struct CompiledPass {
    size_t shaderIndex = 0;  // into the shaders given to build()
    size_t passIndex = 0;    // into LoadedShader::passes
    // Enumeration order; programs index BuildOutput::programs.
    std::vector<pack::PackVariant> variants;
    PassBuildStats stats;
    // Per declared keyword set (PassKeywords::sets order): the stages whose program changes
    // with that set's choice. A set with mask 0 does not affect the pass at all. Empty when a
    // shard (BuildOptions::shard) or a project's plan (LoadedPass::plan) built only some of the
    // pass's variants.
    std::vector<StageMask> setStageEffects;
    // With BuildOptions::keepPrunedSources, per variant (same order) and stage slot: its index
    // into BuildOutput::prunedSources, or kNoProgram for a stage the pass does not have.
    std::vector<std::array<uint32_t, kStageCount>> variantSources;
};

struct BuildOutput {
    std::vector<CompiledPass> passes;
    // One optimised, validated SPIR-V module per distinct program, shared by every variant whose
    // stage compiles to it: deduplicated by bytes, in first-use order, with the source of the
    // pass that first used it.
    std::vector<pack::PackProgram> programs;
    // With BuildOptions::keepPrunedSources: each distinct pruned stage source (what glslang
    // compiled, after preprocessing and pruning to the entry point), in first-use order.
    std::vector<std::string> prunedSources;
    size_t compiledSources = 0;       // glslang compilations
    size_t preprocessedPrograms = 0;  // glslang preprocessing runs (before pruning)
    // Distinct keyword projections over every pass and stage the analysis decided
    // (KeywordProjection.h; stages whose preambles differ only in macros the text cannot name
    // share one), the walks of the text that found them, and the projections it gave up on
    // (every observed keyword kept there).
    size_t keywordProjections = 0, projectionWalks = 0, unprojectedStages = 0;
    // Process CPU time of phase 1 (preprocessing, pruning, interning): all threads. Measured.
    double frontendSeconds = 0;
    size_t cachedSources = 0;       // of compiledSources, taken from the program cache
    size_t cachedStageSources = 0;  // pruned (variant, stage) sources taken from it
    size_t items = 0;               // (variant, stage) items of every pass built
    size_t otherShardItems = 0;     // of items, left to other shards (--shard)
    std::vector<cache::CacheLevelStats> cacheLevels;  // per cache level, in order (none: empty)
    // Sum over compiled sources of their in-process compile CPU time (glslang, optimiser,
    // validator, reflection), excluding preprocessing and dedup: divided by the thread count, the
    // floor a parallel build of these distinct programs cannot beat. Measured: not deterministic.
    double compileSeconds = 0;
};

// Runs the build. Diagnostics name the shader, pass, stage and keywords; an error shared by many
// variants is reported once, with the number of variants it affects. Returns nullopt when any
// program failed (nothing should be written then).
std::optional<BuildOutput> buildPrograms(const std::vector<frontend::LoadedShader>& shaders,
                                         const includes::SourceMap& sourceMap,
                                         const BuildOptions& options, DiagnosticSink& sink);

}  // namespace varc::driver
