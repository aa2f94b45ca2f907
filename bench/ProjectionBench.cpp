// SPDX-License-Identifier: Apache-2.0
// The keyword projection (issue #30): a synthetic pass of 2^n variants (n multi_compile sets)
// whose keywords all appear in the text, of which only d are looked up in the branches the
// preprocessor takes (the others sit under `#if DEPTH > i`, DEPTH = d): 2^d distinct fragment
// programs. With the projection the front end preprocesses once per distinct projection, so
// the build time follows 2^d, not 2^n; without it (projection=0) every variant preprocesses.
// Run: ./build/bench/varc_bench_projection. Results go in docs/PERFORMANCE.md.
#include <benchmark/benchmark.h>

#include <string>

#include "varc/core/Diagnostic.h"
#include "varc/driver/CompileDriver.h"
#include "varc/frontend/ShaderLoader.h"
#include "varc/includes/FileSystem.h"

namespace varc {
namespace {

// n keywords K0..K(n-1); keyword i changes the fragment colour when DEPTH > i.
std::string syntheticShader(int keywords, int depth) {
    std::string text =
        "Shader \"Bench/Projection\" {\n SubShader {\n  Pass {\n   CGPROGRAM\n"
        "   #pragma vertex vert\n   #pragma fragment frag\n";
    for (int i = 0; i < keywords; ++i)
        text += "   #pragma multi_compile _ K" + std::to_string(i) + "\n";
    text += "   #define DEPTH " + std::to_string(depth) + "\n";
    text += "   float4 vert(float4 p : POSITION) : SV_POSITION { return p; }\n";
    text += "   float4 frag() : SV_Target {\n    float4 c = float4(0, 0, 0, 1);\n";
    for (int i = 0; i < keywords; ++i) {
        std::string k = "K" + std::to_string(i);
        text += "   #if DEPTH > " + std::to_string(i) + "\n   #ifdef " + k +
                "\n    c.x += " + std::to_string(1 << (i % 8)) +
                ".0 / 256.0;\n    c.y += " + std::to_string(i + 1) + ".0;\n   #endif\n   #endif\n";
    }
    text += "    return c;\n   }\n   ENDCG\n  }\n }\n}\n";
    return text;
}

// Arguments: n (keywords), d (keywords looked up), projection (1 on, 0 off). One thread, so
// the time is the build's CPU time on an otherwise idle core.
void BM_ProjectedPass(benchmark::State& state) {
    const int keywords = static_cast<int>(state.range(0));
    const int depth = static_cast<int>(state.range(1));
    includes::InMemoryFileSystem fileSystem;
    includes::SourceMap sourceMap;
    DiagnosticList diagnostics;
    fileSystem.add("bench.shader", syntheticShader(keywords, depth));
    auto shader = frontend::loadShader("bench.shader", fileSystem, sourceMap, {}, diagnostics);
    if (!shader) return state.SkipWithError("the synthetic shader failed to load");
    std::vector<frontend::LoadedShader> shaders;
    shaders.push_back(std::move(*shader));
    driver::BuildOptions options;
    options.jobs = 1;
    options.maxVariantsPerPass = 1u << 20;
    options.projectKeywords = state.range(2) != 0;
    std::optional<driver::BuildOutput> output;
    for (auto _ : state) {
        output = driver::buildPrograms(shaders, sourceMap, options, diagnostics);
        if (!output) return state.SkipWithError("build failed");
    }
    state.counters["variants"] = static_cast<double>(output->passes[0].variants.size());
    state.counters["programs"] = static_cast<double>(output->compiledSources);
    state.counters["preprocessed"] = static_cast<double>(output->preprocessedPrograms);
    state.counters["projections"] = static_cast<double>(output->keywordProjections);
    state.counters["frontend_s"] = output->frontendSeconds;
    state.counters["compile_s"] = output->compileSeconds;
}
BENCHMARK(BM_ProjectedPass)
    ->ArgNames({"n", "d", "projection"})
    ->Args({16, 0, 1})
    ->Args({16, 2, 1})
    ->Args({16, 4, 1})
    ->Args({16, 6, 1})
    ->Args({12, 4, 1})
    ->Args({12, 4, 0})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace varc
