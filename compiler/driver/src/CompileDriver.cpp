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
//     (driver/PassJob.h);
//  2. per distinct source: glslang -> SPIRV-Tools optimise -> validate, in parallel, or the
//     program cache (driver/ProgramCompiler.h);
//  3. intern the SPIR-V bytes -> program ids, in enumeration order, and derive the statistics.
//     A shard's items of other shards name one placeholder program per stage and entry point
//     (varc/pack/PartialPack.h); `varc merge` takes their programs from the other parts.
#include "varc/driver/CompileDriver.h"

#include <algorithm>
#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <unordered_map>

#include "DiagnosticGrouper.h"
#include "IncludeChain.h"
#include "jobs/PassJob.h"
#include "jobs/ProgramCompiler.h"
#include "varc/core/JoinWords.h"
#include "varc/driver/CompilerException.h"
#include "varc/driver/GlslLegacyPreamble.h"
#include "varc/driver/GlslVersionDirective.h"
#include "varc/driver/GlslangFrontend.h"
#include "varc/driver/ParallelFor.h"
#include "varc/driver/ProgramCache.h"
#include "varc/driver/StageEffects.h"
#include "varc/pack/PartialPack.h"

namespace varc::driver {

namespace {

using namespace detail;

constexpr size_t kChunkSize = 256;

// What a (variant, stage) item came to, remembered for every item with the same ItemKey.
struct ItemOutcome {
    bool ok = false;
    uint32_t source = kNoProgram;
    std::vector<Diagnostic> diagnostics;
};

// One distinct preprocessed, pruned program.
struct SourceProgram {
    size_t job = 0;
    Stage stage = Stage::Vertex;
    std::string entryPoint;
    std::string text;
    size_t firstVariant = 0;
};

// The file the pass's program text comes from: where its include chains start.
FileId rootFileOf(const PassJob& job) {
    return job.pass->pass->program ? job.pass->pass->program->origin.file : kNoFile;
}

class Builder {
public:
    Builder(const includes::SourceMap& sourceMap, const BuildOptions& options)
        : mSourceMap(sourceMap),
          mOptions(options),
          mThreads(options.jobs ? options.jobs : defaultThreadCount()) {
        if (options.cache) mCache = std::make_unique<ProgramCache>(options.cache);
    }

    bool plan(const std::vector<frontend::LoadedShader>& shaders, DiagnosticSink& sink);
    void chooseShardUnits();
    bool internSources();
    bool compileSources();
    BuildOutput assemble();
    void flushDiagnostics(DiagnosticSink& sink) const { mGrouper.flush(sink); }

    size_t preprocessedPrograms() const { return mPreprocessed; }
    const std::string& cacheError() const { return mCacheError; }
    std::vector<cache::CacheLevelStats> cacheStats() const {
        return mCache ? mCache->chain().stats() : std::vector<cache::CacheLevelStats>{};
    }
    std::vector<std::string> cacheWarnings() const {
        return mCache ? mCache->chain().warnings() : std::vector<std::string>{};
    }
    size_t cachedStageSources() const { return mCachedStageSources; }
    // Writes the shared cache's hits to the local levels in one batch (CacheChain).
    void flushCacheWriteBacks() const {
        if (mCache) mCache->chain().flushWriteBacks();
    }

private:
    bool internChunk(size_t jobIndex, size_t firstItem, size_t count);
    uint32_t internSource(size_t jobIndex, size_t variant, size_t stageIndex, std::string text);
    void applyOutcome(size_t jobIndex, size_t variant, size_t stageIndex,
                      const ItemOutcome& outcome);
    CompiledSource compileSource(const SourceProgram& source) const;
    // The placeholder program that stands for |job|'s items of stage |stageIndex| that other
    // shards build: one per stage slot and entry point.
    uint32_t placeholderOf(const PassJob& job, size_t stageIndex, BuildOutput& output);
    // Reads the cache entries of sources [first, first + count) in one batch.
    void prefetchPrograms(size_t first, size_t count) const;
    // Remembers the first failure to write the cache (thread-safe); the build goes on.
    void noteCacheFailure(const Status& stored) const;
    // Where a program first used by |pass| came from, for runtime error messages.
    pack::SourceInfo sourceInfoOf(const frontend::LoadedPass& pass) const {
        SourceLocation origin = pass.pass->program->origin;
        pack::SourceInfo info{
            mOptions.sourcePaths.map(mSourceMap.path(origin.file)), origin.line, {}};
        for (const std::string& dependency : pass.source.dependencies)
            info.dependencies.push_back(mOptions.sourcePaths.map(dependency));
        return info;
    }
    static std::array<uint32_t, kStageCount> sourcesOf(const PassJob& job, size_t v);
    void fillStats(const PassJob& job, CompiledPass& pass,
                   const std::vector<uint32_t>& finalIds) const;

    const includes::SourceMap& mSourceMap;
    BuildOptions mOptions;
    unsigned mThreads;
    std::vector<PassJob> mJobs;
    std::vector<ShardUnit> mUnits;  // this shard's variants (all of them without --shard)
    size_t mItems = 0;              // (variant, stage) items of every job
    size_t mOwnItems = 0;           // of mItems, this shard's
    std::map<std::pair<size_t, std::string>, uint32_t> mPlaceholders;  // (slot, entry) -> program
    std::vector<SourceProgram> mSources;
    std::unordered_map<std::string, uint32_t> mSourceIndex;           // key: stage|entry|text
    std::unordered_map<ItemKey, ItemOutcome, ItemKeyHash> mOutcomes;  // of the current job
    size_t mPreprocessed = 0;                                         // glslang preprocessing runs
    size_t mCachedStageSources = 0;  // pruned sources read from the cache
    std::vector<CompiledSource> mCompiled;
    DiagnosticGrouper mGrouper;
    std::unique_ptr<ProgramCache> mCache;  // null without a cache in BuildOptions
    mutable std::mutex mCacheErrorMutex;
    mutable std::string mCacheError;  // the first failure to store an entry
};

// Unity compiles a program only for the renderers its `#pragma only_renderers` names and not
// for those `#pragma exclude_renderers` names; varc's renderer is Vulkan ("vulkan"). A pass
// that is not for Vulkan is left out of the build (and the pack) with a note.
bool compiledForVulkan(const frontend::LoadedShader& shader, const frontend::LoadedPass& pass,
                       DiagnosticSink& sink) {
    const variants::PassKeywords& keywords = pass.keywords;
    auto names = [](const std::vector<std::string>& list, std::string_view renderer) {
        return std::find(list.begin(), list.end(), renderer) != list.end();
    };
    bool excluded = names(keywords.excludeRenderers, "vulkan") ||
                    (!keywords.onlyRenderers.empty() && !names(keywords.onlyRenderers, "vulkan"));
    if (!excluded) return true;
    std::string pragma = names(keywords.excludeRenderers, "vulkan")
                             ? "#pragma exclude_renderers " + joinWords(keywords.excludeRenderers)
                             : "#pragma only_renderers " + joinWords(keywords.onlyRenderers);
    sink.report({Severity::Note,
                 pass.pass->program->origin,
                 frontend::describePass(shader.ast, *pass.pass, pass.index) +
                     " is not compiled: its '" + pragma +
                     "' leaves out Vulkan, as Unity leaves it out of Vulkan builds",
                 {}});
    return false;
}

bool Builder::plan(const std::vector<frontend::LoadedShader>& shaders, DiagnosticSink& sink) {
    bool ok = true;
    for (size_t s = 0; s < shaders.size(); ++s) {
        for (size_t p = 0; p < shaders[s].passes.size(); ++p) {
            if (!compiledForVulkan(shaders[s], shaders[s].passes[p], sink)) continue;
            PassJob job;
            job.shaderIndex = s;
            job.passIndex = p;
            job.shader = &shaders[s];
            job.pass = &shaders[s].passes[p];
            if (!collectStages(job, sink) ||
                !frontend::checkVariantLimit(shaders[s], shaders[s].passes[p],
                                             mOptions.maxVariantsPerPass, sink)) {
                ok = false;
                continue;
            }
            job.keys = job.pass->space->enumerate();
            job.text = languageOf(job) == shaderlab::ProgramLanguage::Glsl
                           ? toGlslLineConvention(hoistGlslVersion(job.pass->source.text))
                           : job.pass->source.text;
            job.sourceIds.assign(job.keys.size() * job.stages.size(), kNoProgram);
            if (mOptions.shareUnobservedDefines) job.observed.emplace(job.text);
            job.userDefines.emplace(job.text);
            if (mCache) job.textHash = ProgramCache::hashText(job.text);
            mJobs.push_back(std::move(job));
        }
    }
    return ok;
}

uint32_t Builder::internSource(size_t jobIndex, size_t variant, size_t stageIndex,
                               std::string text) {
    const auto& [stage, entry] = mJobs[jobIndex].stages[stageIndex];
    std::string key = std::to_string(varc::stageIndex(stage)) + "|" + entry + "|" + text;
    auto [it, inserted] =
        mSourceIndex.emplace(std::move(key), static_cast<uint32_t>(mSources.size()));
    if (inserted) mSources.push_back({jobIndex, stage, entry, std::move(text), variant});
    return it->second;
}

void Builder::applyOutcome(size_t jobIndex, size_t variant, size_t stageIndex,
                           const ItemOutcome& outcome) {
    PassJob& job = mJobs[jobIndex];
    if (!outcome.diagnostics.empty()) {
        mGrouper.add(withIncludeChains(outcome.diagnostics, job.text, rootFileOf(job), mSourceMap),
                     job.pass->pass->location,
                     contextOf(job, job.stages[stageIndex].first, variant),
                     {variantId(jobIndex, variant)});
    }
    if (!outcome.ok) return;
    job.sourceIds[variant * job.stages.size() + stageIndex] = outcome.source;
}

// Items [firstItem, firstItem + count) of job |jobIndex| (item = variant * stages + stage):
// preprocesses each distinct preamble once and prunes each distinct (preprocessing, stage) once,
// in parallel, then interns in item order so source ids never depend on thread timing.
bool Builder::internChunk(size_t jobIndex, size_t firstItem, size_t count) {
    const PassJob& job = mJobs[jobIndex];
    const size_t stages = job.stages.size();
    struct Pending {
        size_t preprocess;  // into preambles
        size_t stageIndex;
        StageResult result;
    };
    std::vector<ItemKey> itemKeys(count);
    std::vector<size_t> pendingOf(count, SIZE_MAX);
    std::vector<std::string> preambles;        // distinct preprocessings this chunk needs
    std::vector<size_t> preprocessStageIndex;  // a stage that needs each preprocessing
    std::vector<Pending> pending;
    std::unordered_map<std::string, size_t> preprocessIndex;
    std::unordered_map<ItemKey, size_t, ItemKeyHash> pendingIndex;
    for (size_t i = 0; i < count; ++i) {
        size_t item = firstItem + i;
        size_t variant = item / stages, stageIndex = item % stages;
        const auto& [stage, entry] = job.stages[stageIndex];
        std::string preamble = preambleOf(job, variant, stageIndex);
        std::string preprocessKey = preprocessKeyOf(job, stage, preamble);
        itemKeys[i] = itemKeyOf(preprocessKey, stage, entry);
        if (mOutcomes.count(itemKeys[i])) continue;
        auto [known, inserted] = pendingIndex.emplace(itemKeys[i], pending.size());
        if (inserted) {
            auto [pre, fresh] = preprocessIndex.emplace(std::move(preprocessKey), preambles.size());
            if (fresh) {
                preambles.push_back(std::move(preamble));
                preprocessStageIndex.push_back(stageIndex);
            }
            pending.push_back({pre->second, stageIndex, {}});
        }
        pendingOf[i] = known->second;
    }
    // The program cache may hold a pending item's pruned source already.
    std::vector<char> resolved(pending.size(), 0);
    std::vector<ProgramCacheKey> sourceKeys(mCache ? pending.size() : 0);
    if (mCache) {
        parallelFor(pending.size(), mThreads, [&](size_t p) {
            const auto& [stage, entry] = job.stages[pending[p].stageIndex];
            sourceKeys[p] =
                mCache->sourceKeyOf({job.textHash, languageOf(job), stage, entry,
                                     preambles[pending[p].preprocess], mOptions.pruneStages});
        });
        // One batch per chunk: a remote level answers it in one round trip.
        std::vector<std::optional<std::string>> texts = mCache->loadSources(sourceKeys);
        for (size_t p = 0; p < pending.size(); ++p) {
            if (!texts[p]) continue;
            pending[p].result.ok = true;
            pending[p].result.text = std::move(*texts[p]);
            resolved[p] = 1;
        }
    }
    std::vector<size_t> needed;  // the preprocessings some unresolved item needs
    std::vector<char> isNeeded(preambles.size(), 0);
    for (size_t p = 0; p < pending.size(); ++p) {
        if (!resolved[p]) isNeeded[pending[p].preprocess] = 1;
        mCachedStageSources += resolved[p];
    }
    for (size_t k = 0; k < preambles.size(); ++k) {
        if (isNeeded[k]) needed.push_back(k);
    }
    std::vector<StageResult> preprocessed(preambles.size());
    parallelFor(
        needed.size(), mThreads,
        [&](size_t n) {
            const size_t k = needed[n];
            const auto& [stage, entry] = job.stages[preprocessStageIndex[k]];
            preprocessed[k] = preprocessStage(job, stage, entry, preambles[k], mSourceMap);
        },
        /*firstAlone=*/mSources.empty() && mPreprocessed == 0);
    mPreprocessed += needed.size();
    parallelFor(pending.size(), mThreads, [&](size_t p) {
        if (resolved[p]) return;
        const StageResult& pre = preprocessed[pending[p].preprocess];
        StageResult& result = pending[p].result;
        result.ok = pre.ok;
        result.diagnostics = pre.diagnostics;
        if (!pre.ok) return;
        result.text = pruneStage(job, pre.text, job.stages[pending[p].stageIndex].second, mOptions);
        // Only silent preprocessings are cached: a hit must not lose a warning.
        if (mCache && result.diagnostics.empty()) {
            noteCacheFailure(mCache->storeSource(sourceKeys[p], result.text));
        }
    });
    for (size_t i = 0; i < count; ++i) {
        size_t item = firstItem + i;
        size_t variant = item / stages, stageIndex = item % stages;
        auto known = mOutcomes.find(itemKeys[i]);
        if (known == mOutcomes.end()) {
            StageResult& result = pending[pendingOf[i]].result;
            ItemOutcome outcome{result.ok, kNoProgram, std::move(result.diagnostics)};
            if (result.ok)
                outcome.source =
                    internSource(jobIndex, variant, stageIndex, std::move(result.text));
            known = mOutcomes.emplace(itemKeys[i], std::move(outcome)).first;
        }
        applyOutcome(jobIndex, variant, stageIndex, known->second);
    }
    return !(mGrouper.hasErrors() && !mOptions.keepGoing);
}

// Phase 0: this shard's units, decided from what every machine knows before preprocessing.
void Builder::chooseShardUnits() {
    std::vector<ShardJobSize> sizes;
    for (const PassJob& job : mJobs) {
        sizes.push_back({job.keys.size(), job.stages.size(), job.text.size()});
        mItems += job.keys.size() * job.stages.size();
    }
    mUnits = unitsOfShard(sizes, mOptions.shard);
    for (const ShardUnit& unit : mUnits) mOwnItems += unit.variants * mJobs[unit.job].stages.size();
}

// Phase 1 over this shard's units (in job then variant order): an item's outcome is shared by
// the later items of the same job with the same ItemKey.
bool Builder::internSources() {
    size_t currentJob = SIZE_MAX;
    for (const ShardUnit& unit : mUnits) {
        if (unit.job != currentJob) mOutcomes.clear();
        currentJob = unit.job;
        const size_t stages = mJobs[unit.job].stages.size();
        const size_t first = unit.firstVariant * stages, end = first + unit.variants * stages;
        for (size_t chunk = first; chunk < end; chunk += kChunkSize) {
            if (!internChunk(unit.job, chunk, std::min(kChunkSize, end - chunk))) return false;
        }
    }
    return !mGrouper.hasErrors();
}

void Builder::noteCacheFailure(const Status& stored) const {
    if (stored) return;
    std::lock_guard<std::mutex> lock(mCacheErrorMutex);
    if (mCacheError.empty()) mCacheError = stored.error().detail;
}

void Builder::prefetchPrograms(size_t first, size_t count) const {
    std::vector<ProgramCacheKey> keys(count);
    parallelFor(count, mThreads, [&](size_t n) {
        const SourceProgram& source = mSources[first + n];
        keys[n] = mCache->keyOf({mOptions.optimization, languageOf(mJobs[source.job]), source.stage,
                                 source.entryPoint, source.text});
    });
    mCache->prefetch(keys);
}

CompiledSource Builder::compileSource(const SourceProgram& source) const {
    const PassJob& job = mJobs[source.job];
    const SourceLocation& origin = job.pass->pass->program->origin;
    try {
        return compileStageProgram(
            {source.text, languageOf(job), source.stage, source.entryPoint, origin}, mOptions,
            mCache.get(), mSourceMap, [this](const Status& stored) { noteCacheFailure(stored); });
    } catch (...) {
        CompiledSource failed;
        failed.diagnostics.push_back(
            diagnosticOfCompilerException(std::current_exception(), origin));
        return failed;
    }
}

bool Builder::compileSources() {
    mCompiled.assign(mSources.size(), {});
    std::atomic<bool> failed{false};
    std::atomic<size_t> done{0};
    // In chunks, each chunk's cache entries fetched in one batch first (one round trip per
    // remote level), so a warm shared cache costs no round trip per program.
    for (size_t first = 0; first < mSources.size(); first += kChunkSize) {
        const size_t count = std::min(kChunkSize, mSources.size() - first);
        if (mCache) prefetchPrograms(first, count);
        parallelFor(
            count, mThreads,
            [&](size_t n) {
                const size_t i = first + n;
                if (failed.load() && !mOptions.keepGoing) return;
                double start = threadCpuSeconds();
                mCompiled[i] = compileSource(mSources[i]);
                mCompiled[i].seconds = threadCpuSeconds() - start;
                if (!mCompiled[i].ok) failed.store(true);
                if (mOptions.progress) mOptions.progress(done.fetch_add(1) + 1, mSources.size());
            },
            /*firstAlone=*/first == 0);
        if (failed.load() && !mOptions.keepGoing) break;
    }
    // The variants behind each program with diagnostics, to count each affected variant once.
    std::vector<std::vector<uint64_t>> variantsOf(mSources.size());
    for (size_t j = 0; j < mJobs.size(); ++j) {
        const PassJob& job = mJobs[j];
        for (size_t item = 0; item < job.sourceIds.size(); ++item) {
            uint32_t source = job.sourceIds[item];
            if (source != kNoProgram && !mCompiled[source].diagnostics.empty()) {
                variantsOf[source].push_back(variantId(j, item / job.stages.size()));
            }
        }
    }
    for (size_t i = 0; i < mSources.size(); ++i) {
        const SourceProgram& source = mSources[i];
        if (mCompiled[i].diagnostics.empty()) continue;
        const PassJob& job = mJobs[source.job];
        mGrouper.add(
            withIncludeChains(mCompiled[i].diagnostics, job.text, rootFileOf(job), mSourceMap),
            job.pass->pass->location, contextOf(job, source.stage, source.firstVariant),
            variantsOf[i]);
    }
    return !failed.load() && !mGrouper.hasErrors();
}

void Builder::fillStats(const PassJob& job, CompiledPass& pass,
                        const std::vector<uint32_t>& finalIds) const {
    pass.stats.declaredVariants = job.pass->space->fullCount();
    pass.stats.variants = job.keys.size();
    for (size_t stageIndex = 0; stageIndex < job.stages.size(); ++stageIndex) {
        size_t slot = varc::stageIndex(job.stages[stageIndex].first);
        std::set<uint32_t> sources, modules;
        for (size_t v = 0; v < job.keys.size(); ++v) {
            uint32_t source = job.sourceIds[v * job.stages.size() + stageIndex];
            if (source == kNoProgram) continue;  // another shard's
            sources.insert(source);
            modules.insert(finalIds[source]);
        }
        pass.stats.distinctSources[slot] = sources.size();
        pass.stats.distinctModules[slot] = modules.size();
    }
}

// Per stage slot: the source id variant |v| of |job| compiled, or kNoProgram.
std::array<uint32_t, kStageCount> Builder::sourcesOf(const PassJob& job, size_t v) {
    std::array<uint32_t, kStageCount> ids;
    ids.fill(kNoProgram);
    for (size_t s = 0; s < job.stages.size(); ++s) {
        ids[stageIndex(job.stages[s].first)] = job.sourceIds[v * job.stages.size() + s];
    }
    return ids;
}

uint32_t Builder::placeholderOf(const PassJob& job, size_t stageIndex, BuildOutput& output) {
    const auto& [stage, entry] = job.stages[stageIndex];
    const size_t slot = varc::stageIndex(stage);
    auto [it, inserted] = mPlaceholders.emplace(std::make_pair(slot, entry),
                                                static_cast<uint32_t>(output.programs.size()));
    if (inserted) {
        output.programs.push_back({stage,
                                   entry,
                                   pack::placeholderSpirv(static_cast<uint32_t>(slot)),
                                   {},
                                   sourceInfoOf(*job.pass)});
    }
    return it->second;
}

// Interns SPIR-V bytes in enumeration order, so program ids never depend on thread timing.
BuildOutput Builder::assemble() {
    BuildOutput output;
    output.compiledSources = mSources.size();
    for (const CompiledSource& compiled : mCompiled) output.cachedSources += compiled.fromCache;
    for (const CompiledSource& compiled : mCompiled) output.compileSeconds += compiled.seconds;
    output.items = mItems;
    output.otherShardItems = mItems - mOwnItems;
    std::map<std::vector<uint32_t>, uint32_t> byBytes;
    std::vector<uint32_t> finalIds(mSources.size(), kNoProgram);
    for (const PassJob& job : mJobs) {
        for (uint32_t source : job.sourceIds) {
            if (source == kNoProgram || finalIds[source] != kNoProgram) continue;
            const SourceProgram& program = mSources[source];
            auto [it, inserted] = byBytes.emplace(mCompiled[source].spirv,
                                                  static_cast<uint32_t>(output.programs.size()));
            if (inserted) {
                output.programs.push_back({program.stage, program.entryPoint,
                                           mCompiled[source].spirv, mCompiled[source].reflection,
                                           sourceInfoOf(*job.pass)});
            }
            finalIds[source] = it->second;
        }
    }
    if (mOptions.keepPrunedSources) {
        for (const SourceProgram& source : mSources) output.prunedSources.push_back(source.text);
    }
    for (const PassJob& job : mJobs) {
        CompiledPass pass;
        pass.shaderIndex = job.shaderIndex;
        pass.passIndex = job.passIndex;
        for (size_t v = 0; v < job.keys.size(); ++v) {
            pack::PackVariant variant{job.keys[v], {}};
            variant.programs.fill(kNoProgram);
            for (size_t s = 0; s < job.stages.size(); ++s) {
                uint32_t source = job.sourceIds[v * job.stages.size() + s];
                variant.programs[stageIndex(job.stages[s].first)] =
                    source == kNoProgram ? placeholderOf(job, s, output) : finalIds[source];
            }
            pass.variants.push_back(variant);
            if (mOptions.keepPrunedSources) pass.variantSources.push_back(sourcesOf(job, v));
        }
        fillStats(job, pass, finalIds);
        // Which sets change which stage is only known from every variant's programs.
        bool everyVariant = std::find(job.sourceIds.begin(), job.sourceIds.end(), kNoProgram) ==
                            job.sourceIds.end();
        if (everyVariant)
            pass.setStageEffects = computeSetStageEffects(*job.pass->space, pass.variants);
        output.passes.push_back(std::move(pass));
    }
    return output;
}

}  // namespace

std::optional<BuildOutput> buildPrograms(const std::vector<frontend::LoadedShader>& shaders,
                                         const includes::SourceMap& sourceMap,
                                         const BuildOptions& options, DiagnosticSink& sink) {
    initializeGlslang();
    Builder builder(sourceMap, options);
    // Without --keep-going the first failing phase ends the build; with it, every phase runs so
    // that all errors are reported at once.
    bool ok = builder.plan(shaders, sink);
    builder.chooseShardUnits();
    if (ok || options.keepGoing) ok = builder.internSources() && ok;
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
    output.cachedStageSources = builder.cachedStageSources();
    output.cacheLevels = builder.cacheStats();
    return output;
}

}  // namespace varc::driver
