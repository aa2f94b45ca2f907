// SPDX-License-Identifier: Apache-2.0
// ProgramBuilder: the phases of buildPrograms (see CompileDriver.cpp) over every loaded pass.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "../DiagnosticGrouper.h"
#include "PassJob.h"
#include "ProgramCompiler.h"
#include "varc/driver/CompileDriver.h"
#include "varc/driver/ParallelFor.h"
#include "varc/driver/ProgramCache.h"
#include "varc/driver/ShardPlan.h"

namespace varc::driver::detail {

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

// Plans, preprocesses and prunes, compiles and assembles the programs of every loaded pass;
// buildPrograms runs the phases in order.
class ProgramBuilder {
public:
    ProgramBuilder(const includes::SourceMap& sourceMap, const BuildOptions& options)
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
    // Adds the keyword projections' counts to |output|.
    void projectionStats(BuildOutput& output) const;
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
    struct ChunkPlan;
    bool internChunk(size_t jobIndex, size_t firstItem, size_t count);
    // The steps of internChunk: the chunk's distinct items and preprocessings, their pruned
    // sources from the cache, preprocessing and pruning the rest, interning in item order.
    ChunkPlan planChunk(const PassJob& job, size_t firstItem, size_t count) const;
    void loadCachedSources(const PassJob& job, ChunkPlan& chunk) const;
    void preprocessAndPrune(const PassJob& job, ChunkPlan& chunk);
    void internItems(size_t jobIndex, size_t firstItem, size_t count, ChunkPlan& chunk);
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

}  // namespace varc::driver::detail
