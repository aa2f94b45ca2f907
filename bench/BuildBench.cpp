// SPDX-License-Identifier: Apache-2.0
// Full builds of the seed fixtures and varc's shader library, against two yardsticks:
//   - the naive way: one glslangValidator process per variant and stage (what a shell loop
//     over variants does); target: varc at least 50x faster;
//   - the in-process floor: the distinct programs' own compile time (glslang + optimiser +
//     validator + reflection, summed by the driver) divided by the worker count; target: a
//     parallel build within 1.5x of it.
// Run from anywhere: ./build/bench/varc_bench_build. Results go in docs/PERFORMANCE.md.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "BenchInputs.h"
#include "varc/cache/CacheSpec.h"
#include "varc/core/Diagnostic.h"
#include "varc/driver/CompileDriver.h"
#include "varc/driver/GlslLegacyPreamble.h"
#include "varc/driver/PassDefines.h"
#include "varc/frontend/ShaderLoader.h"
#include "varc/includes/FileSystem.h"

namespace varc {
namespace {

// The fixtures and the library, loaded once: loading is not what these benchmarks measure.
bench::BenchInputs& inputs() {
    static bench::BenchInputs* loaded = [] {
        auto* in = new bench::BenchInputs;
        bench::addLibraryAndFixtures(*in);
        return in;
    }();
    return *loaded;
}

void BM_VarcBuild(benchmark::State& state) {
    bench::BenchInputs& in = inputs();
    if (!in.ok) return state.SkipWithError("inputs failed to load");
    driver::BuildOptions options;
    options.jobs = static_cast<unsigned>(state.range(0));
    // Second argument: 1 = -O (SPIRV-Tools performance passes, the default), 0 = -O0 (no
    // optimiser: what glslangValidator -V produces, the like-for-like comparison).
    options.optimization =
        state.range(1) ? driver::OptimizationLevel::Performance : driver::OptimizationLevel::None;
    std::optional<driver::BuildOutput> output;
    for (auto _ : state) {
        DiagnosticList diagnostics;
        output = driver::buildPrograms(in.shaders, in.sourceMap, options, diagnostics);
        if (!output) return state.SkipWithError("build failed");
    }
    state.counters["variants"] = static_cast<double>(in.variants);
    state.counters["distinct"] = static_cast<double>(output->compiledSources);
    state.counters["modules"] = static_cast<double>(output->programs.size());
    state.counters["preprocessed"] = static_cast<double>(output->preprocessedPrograms);
    // The in-process floor for this thread count, from the last iteration's own compile times.
    state.counters["floor_s"] = output->compileSeconds / options.jobs;
}
BENCHMARK(BM_VarcBuild)
    ->ArgNames({"jobs", "optimize"})
    ->Args({1, 1})
    ->Args({2, 1})
    ->Args({1, 0})
    ->Args({2, 0})
    ->Iterations(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// One glslangValidator process per (pass, variant, stage), on the same spliced source and
// predefined macros varc uses: the start-up-bound baseline the issue measures (~110 ms each).
bool compileWithValidator(const frontend::LoadedPass& pass,
                          const std::vector<std::string>& keywords, Stage stage,
                          const std::string& entry, const std::string& dir) {
    bool glsl = pass.pass->program->language == shaderlab::ProgramLanguage::Glsl;
    driver::DefineContext context{pass.pass->lightMode(),
                                  pass.keywords.target,
                                  pass.pass->program->language,
                                  stage,
                                  keywords,
                                  pass.keywords.instancingOptions};
    std::string source = driver::makePreamble(context);
    if (glsl)
        source = "#version 140\n" + source + driver::legacyGlslPreamble(pass.source.text, stage);
    source += pass.source.text;
    std::string path = dir + (glsl ? "/program.glsl" : "/program.hlsl");
    std::ofstream(path) << source;
    std::string stageFlag = stage == Stage::Vertex ? "vert" : "frag";
    std::string command =
        "glslangValidator -V --quiet --auto-map-bindings --auto-map-locations "
        "--target-env vulkan1.0 -S " +
        stageFlag + " ";
    command += glsl ? "-R " : "-D --hlsl-dx9-compatible -e " + entry + " ";
    command += path + " -o " + dir + "/program.spv > /dev/null 2>&1";
    return std::system(command.c_str()) == 0;
}

// The same build with a warm program cache (--cache-dir): a rebuild after nothing or little
// changed. One untimed build fills the cache; the timed ones read every pruned source and
// compiled program back instead of preprocessing and compiling.
void BM_VarcBuildWarmCache(benchmark::State& state) {
    bench::BenchInputs& in = inputs();
    if (!in.ok) return state.SkipWithError("inputs failed to load");
    driver::BuildOptions options;
    options.jobs = static_cast<unsigned>(state.range(0));
    const std::filesystem::path cacheDirectory =
        std::filesystem::temp_directory_path() / ("varc-bench-cache-" + std::to_string(::getpid()));
    std::filesystem::remove_all(cacheDirectory);
    options.cache = std::make_shared<cache::CacheChain>(
        cache::CacheChain::open({cache::directoryCacheSpec(cacheDirectory.string())}));
    DiagnosticList fill;
    if (!driver::buildPrograms(in.shaders, in.sourceMap, options, fill))
        return state.SkipWithError("build failed");
    std::optional<driver::BuildOutput> output;
    for (auto _ : state) {
        DiagnosticList diagnostics;
        output = driver::buildPrograms(in.shaders, in.sourceMap, options, diagnostics);
        if (!output) return state.SkipWithError("build failed");
    }
    std::filesystem::remove_all(cacheDirectory);
    state.counters["distinct"] = static_cast<double>(output->compiledSources);
    state.counters["cached"] = static_cast<double>(output->cachedSources);
    state.counters["preprocessed"] = static_cast<double>(output->preprocessedPrograms);
}
BENCHMARK(BM_VarcBuildWarmCache)
    ->ArgNames({"jobs"})
    ->Arg(1)
    ->Arg(2)
    ->Iterations(3)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_GlslangValidatorPerVariant(benchmark::State& state) {
    bench::BenchInputs& in = inputs();
    if (!in.ok) return state.SkipWithError("inputs failed to load");
    std::string dir =
        std::filesystem::temp_directory_path() / ("varc-bench-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    size_t processes = 0, failures = 0;
    for (auto _ : state) {
        for (const frontend::LoadedShader& shader : in.shaders) {
            for (const frontend::LoadedPass& pass : shader.passes) {
                bool glsl = pass.pass->program->language == shaderlab::ProgramLanguage::Glsl;
                pass.space->forEach([&](const variants::VariantKey& key) {
                    std::vector<std::string> keywords = pass.space->table().namesOf(key);
                    for (Stage stage : {Stage::Vertex, Stage::Fragment}) {
                        const std::string& entry = stage == Stage::Vertex
                                                       ? pass.keywords.vertexEntry
                                                       : pass.keywords.fragmentEntry;
                        ++processes;
                        if (!compileWithValidator(pass, keywords, stage, glsl ? "main" : entry,
                                                  dir))
                            ++failures;
                    }
                    return true;
                });
            }
        }
    }
    std::filesystem::remove_all(dir);
    state.counters["processes"] = static_cast<double>(processes);
    state.counters["failures"] = static_cast<double>(failures);
    if (failures) state.SkipWithError("some programs failed under glslangValidator");
}
BENCHMARK(BM_GlslangValidatorPerVariant)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace varc
