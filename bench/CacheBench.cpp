// SPDX-License-Identifier: Apache-2.0
// The shared program cache and sharded builds (#12), in one run, on two input sets: the library
// + fixtures, and the library + fixtures + the compatibility corpus (its shaders that build with
// passes of at most 2000 variants). Lines per set:
//   kind 0: cold (empty local folder and empty Redis; every program compiled and stored in both);
//   kind 1: a warm local folder;
//   kind 2: a warm Redis only: a fresh local folder, as a second developer, a CI job or a build
//           farm machine sees it (every hit written back to the folder, in one bundle);
//   kind 3: a warm Redis as the only level (what Redis itself costs, without the write-back);
//   kind 4: a 2-shard build merged, no cache: the time is the slower shard (compile, assemble,
//           write its partial pack) plus the merge (decode both parts, join, write the pack),
//           as two machines and one merge step would take; counters give each part, in wall
//           and in process CPU time (cpu_speedup: less inflated by a busy machine); the merged
//           pack must be the whole build's, byte for byte.
// Target: the warm-Redis build compiles nothing and is at least 20x faster than cold. Starts its
// own redis-server on a free loopback port. Run: ./build/bench/varc_bench_cache. Results go in
// docs/PERFORMANCE.md.
#include <benchmark/benchmark.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "BenchInputs.h"
#include "varc/cache/CacheChain.h"
#include "varc/core/Diagnostic.h"
#include "varc/driver/CompileDriver.h"
#include "varc/driver/PackAssembler.h"
#include "varc/driver/PackMerge.h"
#include "varc/includes/SourcePathMap.h"
#include "varc/pack/PartialPack.h"
#include "varc/packwriter/PackWriter.h"
#include "varc/reader/Pack.h"
#include "varc/reader/PackDecoder.h"

namespace varc {
namespace {

namespace fs = std::filesystem;

// Input set 0: the fixtures and the library; 1: those and the corpus. Loaded once each.
bench::BenchInputs& inputs(int set) {
    static bench::BenchInputs* sets[2] = {};
    if (!sets[set]) {
        sets[set] = new bench::BenchInputs;
        bench::addLibraryAndFixtures(*sets[set]);
        if (set == 1) bench::addBuildableCorpus(*sets[set], 2000, 2);
    }
    return *sets[set];
}

// A redis-server of its own on a free loopback port, stopped at exit.
struct Redis {
    std::string url, dir;
    bool ok = false;
    Redis() {
        int fd = ::socket(AF_INET, SOCK_STREAM, 0);
        sockaddr_in address{};
        address.sin_family = AF_INET;
        address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        socklen_t length = sizeof(address);
        ::bind(fd, reinterpret_cast<sockaddr*>(&address), sizeof(address));
        ::getsockname(fd, reinterpret_cast<sockaddr*>(&address), &length);
        ::close(fd);
        std::string port = std::to_string(ntohs(address.sin_port));
        dir = (fs::temp_directory_path() / ("varc-bench-redis-" + std::to_string(::getpid())))
                  .string();
        fs::create_directories(dir);
        std::string start = "redis-server --bind 127.0.0.1 --port " + port +
                            " --save '' --appendonly no --daemonize yes --pidfile " + dir +
                            "/redis.pid --logfile " + dir + "/redis.log --dir " + dir;
        ok = std::system(start.c_str()) == 0 &&
             std::system(("for i in $(seq 50); do redis-cli -p " + port +
                          " ping >/dev/null 2>&1 && exit 0; sleep 0.1; done; exit 1")
                             .c_str()) == 0;
        url = "redis://127.0.0.1:" + port + "/0";
    }
    ~Redis() {
        (void)std::system(("kill $(cat " + dir + "/redis.pid) 2>/dev/null").c_str());
        std::error_code ignored;
        fs::remove_all(dir, ignored);
    }
};

Redis& redis() {
    static Redis server;
    return server;
}

// A chain of the local folder |local| ("" = none) and the benchmark's Redis.
std::shared_ptr<cache::CacheChain> chain(const std::string& local) {
    std::vector<cache::CacheSpec> specs;
    if (!local.empty()) specs.push_back(*cache::parseCacheSpec("file:" + local));
    specs.push_back(*cache::parseCacheSpec(redis().url));
    return std::make_shared<cache::CacheChain>(cache::CacheChain::open(specs));
}

std::string localDir(const char* name) {
    return (fs::temp_directory_path() /
            ("varc-bench-" + std::string(name) + "-" + std::to_string(::getpid())))
        .string();
}

// Empties both levels (untimed).
void emptyCaches(const std::string& local) {
    fs::remove_all(local);
    (void)chain("")->levels()[0]->clear();
}

std::optional<driver::BuildOutput> build(int set, const std::string& local, unsigned jobs) {
    bench::BenchInputs& in = inputs(set);
    driver::BuildOptions options;
    options.jobs = jobs;
    options.cache = chain(local);
    DiagnosticList diagnostics;
    return driver::buildPrograms(in.shaders, in.sourceMap, options, diagnostics);
}

void report(benchmark::State& state, const driver::BuildOutput& output) {
    state.counters["compiled"] = static_cast<double>(output.compiledSources - output.cachedSources);
    state.counters["modules"] = static_cast<double>(output.programs.size());
}

// Kinds 0-3 (see the top of the file), on input set |set|.
void BM_CacheBuild(benchmark::State& state) {
    const int kind = static_cast<int>(state.range(0));
    const int set = static_cast<int>(state.range(1));
    const unsigned jobs = static_cast<unsigned>(state.range(2));
    if (!inputs(set).ok) return state.SkipWithError("inputs failed to load");
    if (!redis().ok) return state.SkipWithError("redis-server did not start");
    const std::string local = localDir("cache-local"), fresh = localDir("cache-fresh");
    emptyCaches(local);
    if (kind != 0 && !build(set, local, jobs)) return state.SkipWithError("filling build failed");
    std::optional<driver::BuildOutput> output;
    for (auto _ : state) {
        state.PauseTiming();
        if (kind == 0) emptyCaches(local);
        if (kind == 2) fs::remove_all(fresh);
        state.ResumeTiming();
        output = build(set, kind == 2 ? fresh : kind == 3 ? "" : local, jobs);
        if (!output) return state.SkipWithError("build failed");
    }
    report(state, *output);
    state.counters["shaders"] = static_cast<double>(inputs(set).shaders.size());
    if (kind != 0 && output->compiledSources != output->cachedSources)
        state.SkipWithError("a warm build compiled programs");
    fs::remove_all(local);
    fs::remove_all(fresh);
}
BENCHMARK(BM_CacheBuild)
    ->ArgNames({"kind", "set", "jobs"})
    ->ArgsProduct({{0, 1, 2, 3}, {0}, {2}})
    ->Iterations(5)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_CacheBuild)
    ->ArgNames({"kind", "set", "jobs"})
    ->ArgsProduct({{0, 1, 2, 3}, {1}, {2}})
    ->Iterations(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// CPU time of the whole process, every thread: what a build costs whatever else runs beside it.
double processCpuSeconds() {
    timespec now{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

bool fail(const std::string& message) {
    std::fprintf(stderr, "varc_bench_cache: %s\n", message.c_str());
    return false;
}

// Shard |index| of |count| built without a cache and written as a pack (as `varc build
// --shard`; a partial pack unless |count| is 1): the pack's bytes, or "" when the build fails.
std::string buildPart(int set, uint32_t index, uint32_t count, unsigned jobs) {
    bench::BenchInputs& in = inputs(set);
    driver::BuildOptions options;
    options.jobs = jobs;
    options.shard = {index, count};
    DiagnosticList diagnostics;
    std::optional<driver::BuildOutput> output =
        driver::buildPrograms(in.shaders, in.sourceMap, options, diagnostics);
    if (!output) return "";
    std::optional<pack::PackContents> contents = driver::assemblePack(
        in.shaders, *output, in.sourceMap, includes::SourcePathMap(), "bench", diagnostics);
    if (!contents) return "";
    const packwriter::PackWriteOptions write;
    if (!options.shard.whole()) {
        contents->toolchain.push_back({std::string(pack::kShardTool),
                                       options.shard.text() + " level=" +
                                           std::to_string(write.compressionLevel)});
    }
    return packwriter::serializePack(*contents, write);
}

// The merge step of `varc merge`: both parts decoded, joined and written as one pack: its bytes,
// or "" when the merge fails (printed: it would be `varc merge`'s error).
std::string mergeParts(const std::string& first, const std::string& second) {
    std::vector<driver::PartialPackInput> parts;
    reader::OpenOptions open;
    open.acceptPartial = true;
    for (const std::string* bytes : {&first, &second}) {
        Result<reader::Pack> part = reader::Pack::fromBytes(std::string_view(*bytes), open);
        if (!part) {
            fail(part.error().detail);
            return "";
        }
        Result<pack::PackContents> contents = reader::decodePack(*part);
        if (!contents) {
            fail(contents.error().detail);
            return "";
        }
        parts.push_back({"part", std::move(*contents)});
    }
    Result<driver::MergedPack> merged = driver::mergePartialPacks(std::move(parts));
    if (!merged) {
        fail(merged.error().detail);
        return "";
    }
    for (const std::string& error : merged->errors) fail(error);
    if (!merged->errors.empty()) return "";
    packwriter::PackWriteOptions write;
    write.compressionLevel = merged->compressionLevel;
    return packwriter::serializePack(merged->contents, write);
}

// Kind 4: two shards and the merge; the time is the slower shard plus the merge. The same
// iteration also builds the whole pack in one go (no cache), the fair comparison: both write a
// pack; the merged pack must be the whole one, byte for byte.
void BM_ShardedBuild(benchmark::State& state) {
    const int set = static_cast<int>(state.range(0));
    const unsigned jobs = static_cast<unsigned>(state.range(1));
    if (!inputs(set).ok) return state.SkipWithError("inputs failed to load");
    double whole = 0, shard1 = 0, shard2 = 0, merge = 0;
    double wholeCpu = 0, shard1Cpu = 0, shard2Cpu = 0, mergeCpu = 0;
    for (auto _ : state) {
        auto start = std::chrono::steady_clock::now();
        double cpu = processCpuSeconds();
        std::string wholePack = buildPart(set, 1, 1, jobs);
        if (wholePack.empty()) return state.SkipWithError("the build failed");
        whole = secondsSince(start);
        wholeCpu = processCpuSeconds() - cpu;
        start = std::chrono::steady_clock::now();
        cpu = processCpuSeconds();
        std::string first = buildPart(set, 1, 2, jobs);
        shard1 = secondsSince(start);
        shard1Cpu = processCpuSeconds() - cpu;
        start = std::chrono::steady_clock::now();
        cpu = processCpuSeconds();
        std::string second = buildPart(set, 2, 2, jobs);
        shard2 = secondsSince(start);
        shard2Cpu = processCpuSeconds() - cpu;
        if (first.empty() || second.empty()) return state.SkipWithError("a shard failed");
        start = std::chrono::steady_clock::now();
        cpu = processCpuSeconds();
        std::string merged = mergeParts(first, second);
        if (merged.empty()) return state.SkipWithError("the merge failed");
        merge = secondsSince(start);
        mergeCpu = processCpuSeconds() - cpu;
        if (merged != wholePack) return state.SkipWithError("the merged pack is not the whole one");
        state.SetIterationTime(std::max(shard1, shard2) + merge);
    }
    state.counters["whole_ms"] = whole * 1000;
    state.counters["shard1_ms"] = shard1 * 1000;
    state.counters["shard2_ms"] = shard2 * 1000;
    state.counters["merge_ms"] = merge * 1000;
    state.counters["speedup"] = whole / (std::max(shard1, shard2) + merge);
    // The same from every thread's CPU time, which other processes on the machine inflate less.
    state.counters["whole_cpu_ms"] = wholeCpu * 1000;
    state.counters["shard1_cpu_ms"] = shard1Cpu * 1000;
    state.counters["shard2_cpu_ms"] = shard2Cpu * 1000;
    state.counters["merge_cpu_ms"] = mergeCpu * 1000;
    state.counters["cpu_speedup"] = wholeCpu / (std::max(shard1Cpu, shard2Cpu) + mergeCpu);
}
BENCHMARK(BM_ShardedBuild)
    ->ArgNames({"set", "jobs"})
    ->Args({0, 2})
    ->Args({1, 2})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime();

}  // namespace
}  // namespace varc
