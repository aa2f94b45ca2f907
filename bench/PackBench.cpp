// SPDX-License-Identifier: Apache-2.0
// Pack benchmarks: bytes vs raw SPIR-V, lookup time in a ~10^5-variant pack, open time.
#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "varc/packwriter/PackWriter.h"
#include "varc/reader/Pack.h"
#include "varc/reader/PassView.h"

namespace varc {
namespace {

using variants::SelectionPolicy;

constexpr int kSets = 17;             // `#pragma multi_compile _ K<i>`, 2^17 combinations
constexpr uint64_t kSkipped = 0b111;  // skip_variants-like rule: K00 & K01 & K02 never together
constexpr uint32_t kProgramsPerStage = 300;

// SPIR-V-shaped module: a shared prelude (capabilities, types, decorations), then feature
// snippets picked by |seed|'s bits, as variants of one shader differ by #ifdef'd blocks.
std::vector<uint32_t> syntheticSpirv(uint32_t seed, uint32_t stage) {
    std::vector<uint32_t> words = {0x07230203u, 0x00010300u, 0x00080001u, 900u + seed % 64, 0u};
    for (uint32_t i = 0; i < 300; ++i) {
        words.push_back((i % 7 == 0) ? (4u << 16) | 71u : i * 3 + stage);
    }
    for (uint32_t feature = 0; feature < 12; ++feature) {
        std::mt19937 engine(stage * 1000u + feature);
        auto rng = [&engine] { return static_cast<uint32_t>(engine()); };
        bool on = (seed >> (feature % 9)) & 1;
        uint32_t length = 40 + feature * 6;
        for (uint32_t i = 0; i < length; ++i) {
            uint32_t opcode = 61 + rng() % 24;
            words.push_back((4u << 16) | opcode);
            words.push_back(100 + rng() % 200);
            words.push_back(on ? 300 + rng() % 50 : 5u);
            words.push_back(seed * 13 + i);  // result ids differ per module
        }
    }
    return words;
}

struct Synthetic {
    pack::PackContents contents;
    std::string bytes;
    std::string path;
    uint64_t rawVariantBytes = 0;  // sum over variants of their stages' SPIR-V
    packwriter::PackWriteStats stats;
    double serializeSeconds = 0;
    std::vector<variants::VariantKey> hits;    // random existing keys
    std::vector<variants::VariantKey> misses;  // keys with K00 & K01 & K02
};

pack::PackPass syntheticPass(Synthetic& s) {
    pack::PackPass pass;
    pass.lightMode = "ForwardBase";
    for (int i = 0; i < kSets; ++i) {
        char name[8];
        std::snprintf(name, sizeof(name), "K%02d", i);
        pass.keywordTable.push_back(name);
        pass.sets.push_back({"multi_compile", {"", name}});
    }
    // Enumeration order: the first set varies slowest, so bit (kSets-1-i) of the counter is K_i.
    for (uint64_t counter = 0; counter < (uint64_t{1} << kSets); ++counter) {
        uint64_t bits = 0;
        for (int i = 0; i < kSets; ++i) bits |= ((counter >> (kSets - 1 - i)) & 1) << i;
        if ((bits & kSkipped) == kSkipped) continue;
        pack::PackVariant variant;
        variant.key.words()[0] = bits;
        uint64_t mixed = bits * 0x9e3779b97f4a7c15ull;
        variant.programs[0] = static_cast<uint32_t>((mixed >> 40) % kProgramsPerStage);
        variant.programs[1] =
            kProgramsPerStage + static_cast<uint32_t>((mixed >> 20) % kProgramsPerStage);
        s.rawVariantBytes += 4 * (s.contents.programs[variant.programs[0]].spirv.size() +
                                  s.contents.programs[variant.programs[1]].spirv.size());
        pass.variants.push_back(variant);
    }
    return pass;
}

const Synthetic& synthetic() {
    static const Synthetic instance = [] {
        Synthetic s;
        s.contents.toolchain = {{"varc", "bench"}};
        for (uint32_t stage = 0; stage < 2; ++stage) {
            for (uint32_t i = 0; i < kProgramsPerStage; ++i) {
                s.contents.programs.push_back({static_cast<Stage>(stage),
                                               stage == 0 ? "vert" : "frag",
                                               syntheticSpirv(i, stage),
                                               {},
                                               {"Bench.shader", 10 + stage, {}}});
            }
        }
        s.contents.shaders.push_back({"Bench/Synthetic", {syntheticPass(s)}, {}});
        auto start = std::chrono::steady_clock::now();
        s.bytes = packwriter::serializePack(s.contents, {}, &s.stats);
        s.serializeSeconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        s.path = (std::filesystem::temp_directory_path() / "varc_pack_bench.vpk").string();
        if (!packwriter::writePack(s.path, s.contents).ok()) std::abort();
        std::mt19937_64 rng(42);
        const auto& variants = s.contents.shaders[0].passes[0].variants;
        for (int i = 0; i < 4096; ++i) {
            s.hits.push_back(variants[rng() % variants.size()].key);
            variants::VariantKey miss;
            miss.words()[0] = (rng() & ((uint64_t{1} << kSets) - 1)) | kSkipped;
            s.misses.push_back(miss);
        }
        return s;
    }();
    return instance;
}

reader::Pack openSynthetic(bool indexKeys = true) {
    reader::OpenOptions options;
    options.indexKeys = indexKeys;
    Result<reader::Pack> pack = reader::Pack::open(synthetic().path, options);
    if (!pack.ok()) std::abort();
    return std::move(*pack);
}

void BM_PackBytes(benchmark::State& state) {
    const Synthetic& s = synthetic();
    for (auto _ : state) benchmark::DoNotOptimize(s.bytes.size());
    state.counters["variants"] =
        static_cast<double>(s.contents.shaders[0].passes[0].variants.size());
    state.counters["packBytes"] = static_cast<double>(s.bytes.size());
    state.counters["rawVariantSpirvBytes"] = static_cast<double>(s.rawVariantBytes);
    state.counters["rawOverPack"] =
        static_cast<double>(s.rawVariantBytes) / static_cast<double>(s.bytes.size());
    state.counters["distinctSpirvBytes"] = static_cast<double>(s.stats.rawSpirvBytes);
    state.counters["storedBlobBytes"] = static_cast<double>(s.stats.storedBlobBytes);
    state.counters["dictionaryBytes"] = static_cast<double>(s.stats.dictionaryBytes);
    state.counters["serializeSeconds"] = s.serializeSeconds;
}
BENCHMARK(BM_PackBytes)->Iterations(1);

void lookupLoop(benchmark::State& state, const std::vector<variants::VariantKey>& keys,
                SelectionPolicy policy, bool indexKeys = true) {
    reader::Pack pack = openSynthetic(indexKeys);
    reader::PassView pass = *pack.shader(0).pass(0);
    size_t i = 0;
    for (auto _ : state) {
        Result<reader::VariantView> found = pass.lookup(keys[i++ & 4095], policy);
        benchmark::DoNotOptimize(found.ok());
    }
}

void BM_PackLookupExact(benchmark::State& state) {
    lookupLoop(state, synthetic().hits, SelectionPolicy::Exact);
}
BENCHMARK(BM_PackLookupExact);

// The same lookups by binary search (OpenOptions::indexKeys = false), for the ratio.
void BM_PackLookupExactBinarySearch(benchmark::State& state) {
    lookupLoop(state, synthetic().hits, SelectionPolicy::Exact, false);
}
BENCHMARK(BM_PackLookupExactBinarySearch);

void BM_PackLookupClosestHit(benchmark::State& state) {
    lookupLoop(state, synthetic().hits, SelectionPolicy::Closest);
}
BENCHMARK(BM_PackLookupClosestHit);

// A miss falls back to variants::selectVariant, a linear scan over the pass's variants.
void BM_PackLookupClosestMiss(benchmark::State& state) {
    lookupLoop(state, synthetic().misses, SelectionPolicy::Closest);
}
BENCHMARK(BM_PackLookupClosestMiss)->Unit(benchmark::kMicrosecond);

void BM_PackLookupByNames(benchmark::State& state) {
    reader::Pack pack = openSynthetic();
    reader::PassView pass = *pack.shader(0).pass(0);
    std::vector<std::string_view> names = {"K03", "K07", "K11", "K16"};
    for (auto _ : state) {
        benchmark::DoNotOptimize(pass.lookup(names, SelectionPolicy::Exact).ok());
    }
}
BENCHMARK(BM_PackLookupByNames);

void BM_PackOpen(benchmark::State& state) {
    synthetic();
    reader::OpenOptions options{.verifyChecksums = state.range(0) != 0};
    for (auto _ : state) {
        Result<reader::Pack> pack = reader::Pack::open(synthetic().path, options);
        benchmark::DoNotOptimize(pack.ok());
    }
    state.SetLabel(options.verifyChecksums ? "checksums" : "no checksums");
}
BENCHMARK(BM_PackOpen)->Arg(1)->Arg(0)->Unit(benchmark::kMicrosecond);

// First access decompresses; the benchmark reopens the pack every 600 iterations so that it
// measures decompression of each distinct blob.
void BM_PackSpirvFirstAccess(benchmark::State& state) {
    std::optional<reader::Pack> pack;
    size_t i = 0;
    for (auto _ : state) {
        if (i % 600 == 0) {
            state.PauseTiming();
            pack.emplace(openSynthetic());
            state.ResumeTiming();
        }
        benchmark::DoNotOptimize(pack->program(i++ % 600).spirv().ok());
    }
}
BENCHMARK(BM_PackSpirvFirstAccess)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace varc
