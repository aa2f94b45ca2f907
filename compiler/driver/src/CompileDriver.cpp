// SPDX-License-Identifier: Apache-2.0
// Compiles every variant of every loaded pass: each distinct stage program once, in parallel.
//
// Three phases, each deterministic whatever the thread count:
//  0. with --shard K/N: cut the pass jobs into units of whole variants and keep this shard's
//     units (ShardPlan.h), from the plan alone, so every later phase runs on this shard's share;
//  1. per (pass, variant, stage): preprocess with the variant's defines, prune to the entry
//     point, and intern the text -> source ids (identical programs found before glslang runs).
//     Defines the pass text never names are dropped first (ObservedDefines.h), so variants and
//     stages that differ only in those share one preprocessing and one pruning;
//     (driver/PassJob.h). Keywords the preprocessor never looks up in a variant's branches are
//     dropped too (KeywordProjection.h): one preprocessing per distinct projection;
//  2. per distinct source: glslang -> SPIRV-Tools optimise -> validate, in parallel, or the
//     program cache (driver/ProgramCompiler.h);
//  3. intern the SPIR-V bytes -> program ids, in enumeration order, and derive the statistics.
//     A shard's items of other shards name one placeholder program per stage and entry point
//     (varc/pack/PartialPack.h); `varc merge` takes their programs from the other parts.
#include "varc/driver/CompileDriver.h"

#include "jobs/ProgramBuilder.h"
#include "varc/driver/GlslangFrontend.h"

namespace varc::driver {

using detail::processCpuSeconds;
using detail::ProgramBuilder;

std::optional<BuildOutput> buildPrograms(const std::vector<frontend::LoadedShader>& shaders,
                                         const includes::SourceMap& sourceMap,
                                         const BuildOptions& options, DiagnosticSink& sink) {
    initializeGlslang();
    ProgramBuilder builder(sourceMap, options);
    // Without --keep-going the first failing phase ends the build; with it, every phase runs so
    // that all errors are reported at once.
    bool ok = builder.plan(shaders, sink);
    builder.chooseShardUnits();
    const double frontendStart = processCpuSeconds();
    if (ok || options.keepGoing) ok = builder.internSources() && ok;
    const double frontendSeconds = processCpuSeconds() - frontendStart;
    if (ok || options.keepGoing) ok = builder.compileSources() && ok;
    builder.flushCacheWriteBacks();
    builder.flushDiagnostics(sink);
    if (!builder.cacheError().empty()) {
        sink.warning({}, "the program cache is not updated: " + builder.cacheError());
    }
    // One warning per cache level that failed or refused writes; the build went on without it.
    for (const std::string& warning : builder.cacheWarnings()) sink.warning({}, warning);
    if (!ok) return std::nullopt;
    BuildOutput output = builder.assemble();
    output.preprocessedPrograms = builder.preprocessedPrograms();
    builder.projectionStats(output);
    output.frontendSeconds = frontendSeconds;
    output.cachedStageSources = builder.cachedStageSources();
    output.cacheLevels = builder.cacheStats();
    return output;
}

}  // namespace varc::driver