// SPDX-License-Identifier: Apache-2.0
// Benchmarks VariantSpace counting (without enumerating) and forEach over large spaces.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "varc/core/Diagnostic.h"
#include "varc/variants/PragmaParser.h"
#include "varc/variants/VariantSpace.h"

namespace varc::variants {
namespace {

// Builds the space of |texts| (one pragma each); aborts on a diagnostic error since the inputs
// are fixed and valid.
VariantSpace spaceOf(const std::vector<std::string>& texts) {
    std::vector<PragmaLine> lines;
    for (size_t i = 0; i < texts.size(); ++i) {
        lines.push_back({texts[i], SourceLocation{0, static_cast<uint32_t>(i + 1), 1}});
    }
    DiagnosticList sink;
    std::optional<PassKeywords> keywords = parsePragmas(lines, sink);
    std::optional<VariantSpace> space =
        keywords ? VariantSpace::build(*keywords, sink) : std::nullopt;
    if (!space) std::abort();
    return std::move(*space);
}

std::vector<std::string> independentSets(int n) {
    std::vector<std::string> texts;
    for (int i = 0; i < n; ++i) texts.push_back("multi_compile _ K" + std::to_string(i));
    return texts;
}

void countIndependent(benchmark::State& state) {
    VariantSpace space = spaceOf(independentSets(static_cast<int>(state.range(0))));
    for (auto _ : state) benchmark::DoNotOptimize(space.count());
    state.counters["variants"] = static_cast<double>(space.count());
}
BENCHMARK(countIndependent)->Arg(18)->Arg(64);

void countLightPassHdr(benchmark::State& state) {
    VariantSpace space = spaceOf({"multi_compile_lightpass", "multi_compile ___ UNITY_HDR_ON"});
    for (auto _ : state) benchmark::DoNotOptimize(space.count());
    state.counters["variants"] = static_cast<double>(space.count());
}
BENCHMARK(countLightPassHdr);

void countFwdBase(benchmark::State& state) {
    VariantSpace space = spaceOf({"multi_compile_fwdbase", "multi_compile_fog"});
    for (auto _ : state) benchmark::DoNotOptimize(space.count());
    state.counters["variants"] = static_cast<double>(space.count());
}
BENCHMARK(countFwdBase);

void forEachIndependent18(benchmark::State& state) {
    VariantSpace space = spaceOf(independentSets(18));
    for (auto _ : state) {
        size_t bits = 0;
        space.forEach([&bits](const VariantKey& key) {
            bits += key.words()[0] & 1u;
            return true;
        });
        benchmark::DoNotOptimize(bits);
    }
    state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(space.count()));
}
BENCHMARK(forEachIndependent18)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace varc::variants
