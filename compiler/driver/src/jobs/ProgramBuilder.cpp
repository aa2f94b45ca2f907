// SPDX-License-Identifier: Apache-2.0
// ProgramBuilder: plans the pass jobs, interns their pruned sources, compiles each distinct
// source once and assembles programs and passes in enumeration order.
#include "ProgramBuilder.h"

#include <algorithm>
#include <atomic>
#include <optional>
#include <set>

#include "../IncludeChain.h"
#include "varc/core/JoinWords.h"
#include "varc/driver/CompilerException.h"
#include "varc/driver/GlslLegacyPreamble.h"
#include "varc/driver/GlslVersionDirective.h"
#include "varc/driver/GlslangFrontend.h"
#include "varc/driver/ParallelFor.h"
#include "varc/driver/StageEffects.h"
#include "varc/frontend/VariantLimit.h"
#include "varc/pack/PartialPack.h"
#include "varc/variants/VariantSample.h"

namespace varc::driver::detail {

namespace {

// The file the pass's program text comes from: where its include chains start.
FileId rootFileOf(const PassJob& job) {
    return job.pass->pass->program ? job.pass->pass->program->origin.file : kNoFile;
}

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

}  // namespace

// What internChunk learns about its items before preprocessing anything.
struct ProgramBuilder::ChunkPlan {
    struct Pending {
        size_t preprocess;  // into preambles
        size_t stageIndex;
        StageResult result;
        // The pruner returned the text whole although its projection left out lookups in
        // unreachable bodies: the item must be planned again with every lookup.
        bool unprunable = false;
    };
    std::vector<ItemKey> itemKeys;             // per item
    std::vector<size_t> pendingOf;             // per item: into pending, or SIZE_MAX (known)
    std::vector<std::string> preambles;        // distinct preprocessings this chunk needs
    std::vector<size_t> preprocessStageIndex;  // a stage that needs each preprocessing
    std::vector<Pending> pending;              // the distinct items not seen before
    std::vector<char> resolved;                // per pending item: read from the cache
    std::vector<ProgramCacheKey> sourceKeys;   // per pending item, with a cache
};

bool ProgramBuilder::plan(const std::vector<frontend::LoadedShader>& shaders,
                          DiagnosticSink& sink) {
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
            // A project's plan lists what ships; without one every declared variant does.
            job.keys = job.pass->plan ? job.pass->plan->keys : job.pass->space->enumerate();
            job.keys = variants::sampleEvenly(std::move(job.keys), mOptions.sampleVariantsPerPass);
            job.text = languageOf(job) == shaderlab::ProgramLanguage::Glsl
                           ? toGlslLineConvention(hoistGlslVersion(job.pass->source.text))
                           : job.pass->source.text;
            job.sourceIds.assign(job.keys.size() * job.stages.size(), kNoProgram);
            if (mOptions.shareUnobservedDefines) job.observed.emplace(job.text);
            job.userDefines.emplace(job.text);
            if (mCache) job.textHash = ProgramCache::hashText(job.text);
            if (mOptions.projectKeywords)
                setUpProjections(job, mOptions.pruneStages && mOptions.projectReachableCode);
            mJobs.push_back(std::move(job));
        }
    }
    return ok;
}

uint32_t ProgramBuilder::internSource(size_t jobIndex, size_t variant, size_t stageIndex,
                                      std::string text) {
    const auto& [stage, entry] = mJobs[jobIndex].stages[stageIndex];
    std::string key = std::to_string(varc::stageIndex(stage)) + "|" + entry + "|" + text;
    auto [it, inserted] =
        mSourceIndex.emplace(std::move(key), static_cast<uint32_t>(mSources.size()));
    if (inserted) mSources.push_back({jobIndex, stage, entry, std::move(text), variant});
    return it->second;
}

void ProgramBuilder::applyOutcome(size_t jobIndex, size_t variant, size_t stageIndex,
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
bool ProgramBuilder::internChunk(size_t jobIndex, size_t firstItem, size_t count) {
    const PassJob& job = mJobs[jobIndex];
    ChunkPlan chunk;
    for (bool again = true; again;) {
        chunk = planChunk(job, firstItem, count);
        // The program cache may hold a pending item's pruned source already.
        chunk.resolved.assign(chunk.pending.size(), 0);
        chunk.sourceKeys.resize(mCache ? chunk.pending.size() : 0);
        if (mCache) loadCachedSources(job, chunk);
        preprocessAndPrune(job, chunk);
        // Rare (a text the pruner cannot parse): such a stage counts every lookup from here on.
        again = false;
        for (const ChunkPlan::Pending& pending : chunk.pending) {
            if (!pending.unprunable) continue;
            job.projections[pending.stageIndex]->keepUnreachableLookups();
            again = true;
        }
    }
    internItems(jobIndex, firstItem, count, chunk);
    return !(mGrouper.hasErrors() && !mOptions.keepGoing);
}

ProgramBuilder::ChunkPlan ProgramBuilder::planChunk(const PassJob& job, size_t firstItem,
                                                    size_t count) const {
    const size_t stages = job.stages.size();
    ChunkPlan chunk;
    chunk.itemKeys.resize(count);
    chunk.pendingOf.assign(count, SIZE_MAX);
    std::unordered_map<std::string, size_t> preprocessIndex;
    std::unordered_map<ItemKey, size_t, ItemKeyHash> pendingIndex;
    for (size_t i = 0; i < count; ++i) {
        size_t item = firstItem + i;
        size_t variant = item / stages, stageIndex = item % stages;
        const auto& [stage, entry] = job.stages[stageIndex];
        std::string preamble = preambleOf(job, variant, stageIndex);
        std::string preprocessKey = preprocessKeyOf(job, stage, preamble);
        chunk.itemKeys[i] = itemKeyOf(preprocessKey, stage, entry);
        if (mOutcomes.count(chunk.itemKeys[i])) continue;
        auto [known, inserted] = pendingIndex.emplace(chunk.itemKeys[i], chunk.pending.size());
        if (inserted) {
            auto [pre, fresh] =
                preprocessIndex.emplace(std::move(preprocessKey), chunk.preambles.size());
            if (fresh) {
                chunk.preambles.push_back(std::move(preamble));
                chunk.preprocessStageIndex.push_back(stageIndex);
            }
            chunk.pending.push_back({pre->second, stageIndex, {}, false});
        }
        chunk.pendingOf[i] = known->second;
    }
    return chunk;
}

void ProgramBuilder::loadCachedSources(const PassJob& job, ChunkPlan& chunk) const {
    std::vector<ChunkPlan::Pending>& pending = chunk.pending;
    parallelFor(pending.size(), mThreads, [&](size_t p) {
        const auto& [stage, entry] = job.stages[pending[p].stageIndex];
        const bool withoutUnreachable =
            !job.projections.empty() &&
            job.projections[pending[p].stageIndex]->leavesOutUnreachable();
        chunk.sourceKeys[p] = mCache->sourceKeyOf({job.textHash, languageOf(job), stage, entry,
                                                   chunk.preambles[pending[p].preprocess],
                                                   mOptions.pruneStages, withoutUnreachable});
    });
    // One batch per chunk: a remote level answers it in one round trip.
    std::vector<std::optional<std::string>> texts = mCache->loadSources(chunk.sourceKeys);
    for (size_t p = 0; p < pending.size(); ++p) {
        if (!texts[p]) continue;
        pending[p].result.ok = true;
        pending[p].result.text = std::move(*texts[p]);
        chunk.resolved[p] = 1;
    }
}

void ProgramBuilder::preprocessAndPrune(const PassJob& job, ChunkPlan& chunk) {
    std::vector<ChunkPlan::Pending>& pending = chunk.pending;
    const std::vector<char>& resolved = chunk.resolved;
    std::vector<size_t> needed;  // the preprocessings some unresolved item needs
    std::vector<char> isNeeded(chunk.preambles.size(), 0);
    for (size_t p = 0; p < pending.size(); ++p) {
        if (!resolved[p]) isNeeded[pending[p].preprocess] = 1;
        mCachedStageSources += resolved[p];
    }
    for (size_t k = 0; k < chunk.preambles.size(); ++k) {
        if (isNeeded[k]) needed.push_back(k);
    }
    std::vector<StageResult> preprocessed(chunk.preambles.size());
    parallelFor(
        needed.size(), mThreads,
        [&](size_t n) {
            const size_t k = needed[n];
            const auto& [stage, entry] = job.stages[chunk.preprocessStageIndex[k]];
            preprocessed[k] = preprocessStage(job, stage, entry, chunk.preambles[k], mSourceMap);
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
        const size_t stageIndex = pending[p].stageIndex;
        bool pruned = false;
        result.text = pruneStage(job, pre.text, job.stages[stageIndex].second, mOptions, pruned);
        pending[p].unprunable = !pruned && !job.projections.empty() &&
                                job.projections[stageIndex]->leavesOutUnreachable();
        // Only silent preprocessings are cached: a hit must not lose a warning.
        if (mCache && result.diagnostics.empty() && !pending[p].unprunable) {
            noteCacheFailure(mCache->storeSource(chunk.sourceKeys[p], result.text));
        }
    });
}

void ProgramBuilder::internItems(size_t jobIndex, size_t firstItem, size_t count,
                                 ChunkPlan& chunk) {
    const size_t stages = mJobs[jobIndex].stages.size();
    for (size_t i = 0; i < count; ++i) {
        size_t item = firstItem + i;
        size_t variant = item / stages, stageIndex = item % stages;
        auto known = mOutcomes.find(chunk.itemKeys[i]);
        if (known == mOutcomes.end()) {
            StageResult& result = chunk.pending[chunk.pendingOf[i]].result;
            ItemOutcome outcome{result.ok, kNoProgram, std::move(result.diagnostics)};
            if (result.ok)
                outcome.source =
                    internSource(jobIndex, variant, stageIndex, std::move(result.text));
            known = mOutcomes.emplace(chunk.itemKeys[i], std::move(outcome)).first;
        }
        applyOutcome(jobIndex, variant, stageIndex, known->second);
    }
}

// Phase 0: this shard's units, decided from what every machine knows before preprocessing.
void ProgramBuilder::chooseShardUnits() {
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
bool ProgramBuilder::internSources() {
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

void ProgramBuilder::projectionStats(BuildOutput& output) const {
    for (const PassJob& job : mJobs) {
        std::set<const KeywordProjection*> seen;  // stages may share one
        for (const std::shared_ptr<KeywordProjection>& projection : job.projections) {
            if (!seen.insert(projection.get()).second) continue;
            output.keywordProjections += projection->projections();
            output.projectionWalks += projection->walks();
            output.unprojectedStages += projection->usable() ? 0 : 1;
        }
    }
}

void ProgramBuilder::noteCacheFailure(const Status& stored) const {
    if (stored) return;
    std::lock_guard<std::mutex> lock(mCacheErrorMutex);
    if (mCacheError.empty()) mCacheError = stored.error().detail;
}

void ProgramBuilder::prefetchPrograms(size_t first, size_t count) const {
    std::vector<ProgramCacheKey> keys(count);
    parallelFor(count, mThreads, [&](size_t n) {
        const SourceProgram& source = mSources[first + n];
        keys[n] = mCache->keyOf({mOptions.optimization, languageOf(mJobs[source.job]), source.stage,
                                 source.entryPoint, source.text});
    });
    mCache->prefetch(keys);
}

CompiledSource ProgramBuilder::compileSource(const SourceProgram& source) const {
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

bool ProgramBuilder::compileSources() {
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

void ProgramBuilder::fillStats(const PassJob& job, CompiledPass& pass,
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
std::array<uint32_t, kStageCount> ProgramBuilder::sourcesOf(const PassJob& job, size_t v) {
    std::array<uint32_t, kStageCount> ids;
    ids.fill(kNoProgram);
    for (size_t s = 0; s < job.stages.size(); ++s) {
        ids[stageIndex(job.stages[s].first)] = job.sourceIds[v * job.stages.size() + s];
    }
    return ids;
}

uint32_t ProgramBuilder::placeholderOf(const PassJob& job, size_t stageIndex, BuildOutput& output) {
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
BuildOutput ProgramBuilder::assemble() {
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
        // Which sets change which stage is only known from every variant's programs: not when
        // another shard or a project's plan left some out.
        bool everyVariant = std::find(job.sourceIds.begin(), job.sourceIds.end(), kNoProgram) ==
                                job.sourceIds.end() &&
                            job.keys.size() == job.pass->space->count();
        if (everyVariant)
            pass.setStageEffects = computeSetStageEffects(*job.pass->space, pass.variants);
        output.passes.push_back(std::move(pass));
    }
    return output;
}

}  // namespace varc::driver::detail
