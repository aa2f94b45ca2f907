// SPDX-License-Identifier: Apache-2.0
// ProgramCache: a directory of compiled stage programs keyed by everything that determines them,
// so a rebuild compiles only the programs it has not seen before (what ccache does for C++ and
// Unreal's derived-data cache for shader permutations), and of preprocessed, pruned stage sources,
// so it does not even preprocess what it has seen.
//
// The key hashes (XXH3-128) the running executable's GNU build ID (or, without one, its bytes), so
// a rebuilt varc never reuses another build's output, the optimisation level, language, stage,
// entry point and the pruned, preprocessed program text, which already holds every define and
// include. An entry stores the optimised, validated SPIR-V, the HLSL semantics reflection needs and
// glslang's log (so warnings are reported again on a hit). Entries are written atomically
// (temporary file, then rename), so concurrent builds can share a directory; an entry that is
// truncated, corrupt or for another key is ignored and recompiled, never trusted. Failed compiles
// are not cached. Nothing is ever evicted: delete the directory to reclaim space.
//
// Where entries live is a cache::CacheChain (a local folder, then shared levels such as Redis,
// each entry named "<key hex>.program" or ".source"); this class computes keys, (de)serialises
// entries and checks them, so a damaged value from any level is a miss.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "varc/cache/CacheChain.h"
#include "varc/core/Result.h"
#include "varc/core/Stage.h"
#include "varc/driver/SpirvOptimizer.h"
#include "varc/driver/SpirvReflection.h"
#include "varc/shaderlab/ShaderAst.h"

namespace varc::driver {

struct ProgramCacheKey {
    uint64_t low = 0, high = 0;
    bool operator==(const ProgramCacheKey&) const = default;
    std::string hex() const;  // 32 lowercase hex digits
};

// What a cached compile produced.
struct CachedProgram {
    std::vector<uint32_t> spirv;     // optimised and validated, with debug names
    std::vector<uint32_t> stripped;  // the same without debug names (what ships by default)
    SemanticsByLocation semantics;   // from the module before optimisation
    std::string log;                 // glslang's messages, unmapped
};

// Everything besides the executable that determines a compiled program.
struct ProgramCacheInput {
    OptimizationLevel optimization = OptimizationLevel::Performance;
    shaderlab::ProgramLanguage language = shaderlab::ProgramLanguage::Cg;
    Stage stage = Stage::Vertex;
    std::string_view entryPoint;
    std::string_view text;  // preprocessed and pruned
};

// Everything besides the executable that determines a preprocessed, pruned stage source.
struct SourceCacheInput {
    ProgramCacheKey passText;  // ProgramCache::hashText of the expanded pass source
    shaderlab::ProgramLanguage language = shaderlab::ProgramLanguage::Cg;
    Stage stage = Stage::Vertex;
    std::string_view entryPoint;
    std::string_view preamble;  // the defines the text observes (+ the legacy GLSL preamble)
    bool pruned = true;
    // The preamble left out keywords looked up only in unreachable bodies: the entry then
    // holds only a pruned text (a text the pruner returned whole is never stored under it).
    bool withoutUnreachable = false;
};

class ProgramCache {
public:
    // Uses the levels of |chain| (not null), shared with whoever reads its statistics afterwards.
    // A folder alone: CacheChain::open({cache::directoryCacheSpec(DIR)}), created on the first
    // store, each entry at DIR/<2 hex>/<entryName>.
    explicit ProgramCache(std::shared_ptr<cache::CacheChain> chain);

    ProgramCacheKey keyOf(const ProgramCacheInput& input) const;
    ProgramCacheKey sourceKeyOf(const SourceCacheInput& input) const;
    static ProgramCacheKey hashText(std::string_view text);
    // Identifies the running executable (its GNU build ID, else its bytes): what every key holds,
    // so a rebuilt varc never reuses another build's entries.
    static ProgramCacheKey executableKey();

    // The entry for |key|; nullopt when there is none or it cannot be trusted.
    std::optional<CachedProgram> load(const ProgramCacheKey& key) const;

    // Writes the entry for |key| atomically. Errors name the file and the reason.
    Status store(const ProgramCacheKey& key, const CachedProgram& program) const;

    // Fetches the program entries for |keys| from every level at once (one round trip per remote
    // level, not one per key); load() then takes each from memory. Thread-safe.
    void prefetch(const std::vector<ProgramCacheKey>& keys) const;

    // The pruned source for |key|, or nullopt; many at once (batched like prefetch); storing one.
    std::optional<std::string> loadSource(const ProgramCacheKey& key) const;
    std::vector<std::optional<std::string>> loadSources(
        const std::vector<ProgramCacheKey>& keys) const;
    Status storeSource(const ProgramCacheKey& key, std::string_view text) const;

    // An entry's name in every level: <32 hex><extension> (".program", ".source").
    static std::string entryName(const ProgramCacheKey& key, std::string_view extension);
    cache::CacheChain& chain() const { return *mChain; }

private:
    std::vector<std::optional<std::string>> loadPayloads(const std::vector<ProgramCacheKey>& keys,
                                                         std::string_view magic,
                                                         std::string_view extension) const;
    Status storePayload(const ProgramCacheKey& key, std::string_view magic,
                        std::string_view extension, std::string_view payload) const;

    std::shared_ptr<cache::CacheChain> mChain;
    ProgramCacheKey mToolchain;  // hash of the running executable
    mutable std::mutex mPrefetchMutex;
    // Program payloads prefetch() read, by key hex, until load() takes them (nullopt: a miss).
    mutable std::unordered_map<std::string, std::optional<std::string>> mPrefetched;
};

}  // namespace varc::driver
