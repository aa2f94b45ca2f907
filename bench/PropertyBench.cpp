// SPDX-License-Identifier: Apache-2.0
// Property validation (issue #16) of the whole library pack (varc's library and the seed
// fixtures) on lavapipe, end to end as `varc validate --properties` runs it: device, renderer,
// every lit shader's scenes and relations. Cold = Mesa's on-disk shader cache disabled (every
// pipeline compiled), warm = its cache filled by an earlier run. The target: under 60 s.
// Needs the test pack: build the project with tests, run ctest -R vulkan.build_packs once, then
//   ./build/bench/varc_bench_properties
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <optional>

#include "varc/properties/PropertyRunner.h"
#include "varc/reader/Pack.h"
#include "varc/render/SceneRenderer.h"
#include "varc/vulkan/VulkanContext.h"

namespace varc::render {
namespace {

constexpr const char* kPack = VARC_BINARY_DIR "/tests/vulkan/packs/library.svpack";
constexpr const char* kMesaCache = VARC_BINARY_DIR "/bench-mesa-cache";
constexpr const char* kOut = VARC_BINARY_DIR "/bench-properties-out";

// Mesa reads MESA_SHADER_CACHE_DISABLE when the device is created.
void chooseMesaCache(bool cold) {
    if (cold) {
        setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
    } else {
        unsetenv("MESA_SHADER_CACHE_DISABLE");
        setenv("MESA_SHADER_CACHE_DIR", kMesaCache, 1);
    }
}

// One whole run: the relations of every lit shader; the shader, render and failure counts.
struct RunCounts {
    size_t shaders = 0, renders = 0, failed = 0;
};
std::optional<RunCounts> validateLibrary(const reader::Pack& pack, std::string& error) {
    auto context = vulkan::VulkanContext::create();
    if (!context) {
        error = "no Vulkan device";
        return std::nullopt;
    }
    auto renderer = SceneRenderer::create(*context, {&pack});
    if (!renderer) {
        error = renderer.error().detail;
        return std::nullopt;
    }
    properties::PropertyOptions options;
    options.outDir = kOut;
    properties::PropertyRunner runner(*renderer, options);
    RunCounts counts;
    for (const reader::ShaderView& shader : properties::lightingShaders({&pack})) {
        properties::ShaderReport report = runner.check(shader);
        ++counts.shaders;
        counts.renders += report.renders;
        if (!report.passed()) ++counts.failed;
    }
    return counts;
}

void BM_PropertyValidationOfTheLibrary(benchmark::State& state) {
    const bool cold = state.range(0) == 0;
    state.SetLabel(cold ? "cold Mesa cache" : "warm Mesa cache");
    auto pack = reader::Pack::open(kPack);
    if (!pack) return state.SkipWithError("test pack missing: run ctest -R vulkan.build_packs");
    chooseMesaCache(cold);
    std::string error;
    if (!cold && !validateLibrary(*pack, error)) return state.SkipWithError(error.c_str());
    RunCounts counts;
    for (auto _ : state) {
        std::optional<RunCounts> run = validateLibrary(*pack, error);
        if (!run) return state.SkipWithError(error.c_str());
        counts = *run;
    }
    if (counts.failed > 0) return state.SkipWithError("a library shader fails a relation");
    state.counters["shaders"] = static_cast<double>(counts.shaders);
    state.counters["renders"] = static_cast<double>(counts.renders);
}
BENCHMARK(BM_PropertyValidationOfTheLibrary)
    ->Arg(0)
    ->Arg(1)
    ->Iterations(3)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

}  // namespace
}  // namespace varc::render
