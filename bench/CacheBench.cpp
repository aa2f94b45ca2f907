// SPDX-License-Identifier: Apache-2.0
// The shared program cache (#12) on the library + fixtures, in one run: a cold build (empty local
// folder and empty Redis; every program compiled and stored in both), a build with a warm local
// folder, and a build with a warm Redis only (a fresh local folder, as a second developer, a CI
// job or a build farm machine sees it). Target: the warm-Redis build compiles nothing and is at
// least 20x faster than cold. Starts its own redis-server on a free loopback port.
// Run from anywhere: ./build/bench/varc_bench_cache. Results go in docs/PERFORMANCE.md.
#include <benchmark/benchmark.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "varc/build/CompileDriver.h"
#include "varc/cache/CacheChain.h"
#include "varc/core/Diagnostic.h"
#include "varc/frontend/ShaderLoader.h"
#include "varc/includes/FileSystem.h"

namespace varc {
namespace {

namespace fs = std::filesystem;

struct Inputs {
    includes::DiskFileSystem fileSystem;
    includes::SourceMap sourceMap;
    std::vector<compiler::LoadedShader> shaders;
    bool ok = true;
};

// The fixtures and the shader library, loaded once: loading is not what is measured.
Inputs& inputs() {
    static Inputs* loaded = [] {
        auto* in = new Inputs;
        std::vector<std::string> files;
        for (const char* root :
             {VARC_SOURCE_DIR "/../shared/fixtures", VARC_SOURCE_DIR "/shaders"}) {
            if (!fs::is_directory(root)) continue;
            for (const auto& entry : fs::recursive_directory_iterator(root)) {
                if (entry.path().extension() == ".shader") files.push_back(entry.path().string());
            }
        }
        std::sort(files.begin(), files.end());
        includes::IncludeOptions options;
        options.builtinDir = VARC_SOURCE_DIR "/shaders/builtin";
        DiagnosticList diagnostics;
        for (const std::string& file : files) {
            auto shader =
                compiler::loadShader(file, in->fileSystem, in->sourceMap, options, diagnostics);
            if (shader) in->shaders.push_back(std::move(*shader));
        }
        in->ok = !diagnostics.hasErrors() && !in->shaders.empty();
        return in;
    }();
    return *loaded;
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

std::optional<compiler::BuildOutput> build(const std::string& local, unsigned jobs) {
    Inputs& in = inputs();
    compiler::BuildOptions options;
    options.jobs = jobs;
    options.cache = chain(local);
    DiagnosticList diagnostics;
    return compiler::buildPrograms(in.shaders, in.sourceMap, options, diagnostics);
}

void report(benchmark::State& state, const compiler::BuildOutput& output) {
    state.counters["compiled"] = static_cast<double>(output.compiledSources - output.cachedSources);
    state.counters["modules"] = static_cast<double>(output.programs.size());
}

// Kind 0: cold (both levels emptied before each build); 1: warm local folder; 2: warm Redis,
// fresh local folder before each build (every hit written back to it); 3: warm Redis as the only
// level (what Redis itself costs, without the write-back).
void BM_CacheBuild(benchmark::State& state) {
    if (!inputs().ok) return state.SkipWithError("inputs failed to load");
    if (!redis().ok) return state.SkipWithError("redis-server did not start");
    const int kind = static_cast<int>(state.range(0));
    const unsigned jobs = static_cast<unsigned>(state.range(1));
    const std::string local = localDir("cache-local"), fresh = localDir("cache-fresh");
    emptyCaches(local);
    if (kind != 0 && !build(local, jobs)) return state.SkipWithError("filling build failed");
    std::optional<compiler::BuildOutput> output;
    for (auto _ : state) {
        state.PauseTiming();
        if (kind == 0) emptyCaches(local);
        if (kind == 2) fs::remove_all(fresh);
        state.ResumeTiming();
        output = build(kind == 2 ? fresh : kind == 3 ? "" : local, jobs);
        if (!output) return state.SkipWithError("build failed");
    }
    report(state, *output);
    if (kind != 0 && output->compiledSources != output->cachedSources)
        state.SkipWithError("a warm build compiled programs");
    fs::remove_all(local);
    fs::remove_all(fresh);
}
BENCHMARK(BM_CacheBuild)
    ->ArgNames({"kind", "jobs"})
    ->Args({0, 2})
    ->Args({1, 2})
    ->Args({2, 2})
    ->Args({3, 2})
    ->Iterations(5)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace varc
