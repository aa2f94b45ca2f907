// SPDX-License-Identifier: Apache-2.0
// Benchmarks VariantSpace counting (without enumerating), forEach, and material selection.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "varc/core/Diagnostic.h"
#include "varc/variants/MaterialSelection.h"
#include "varc/variants/PragmaParser.h"
#include "varc/variants/VariantSpace.h"

namespace varc::variants {
namespace {

// Builds the space of |texts| (one pragma each); aborts on a diagnostic error since the inputs
// are fixed and valid.
PassKeywords keywordsOf(const std::vector<std::string>& texts) {
    std::vector<PragmaLine> lines;
    for (size_t i = 0; i < texts.size(); ++i) {
        lines.push_back({texts[i], SourceLocation{0, static_cast<uint32_t>(i + 1), 1}});
    }
    DiagnosticList sink;
    std::optional<PassKeywords> keywords = parsePragmas(lines, sink);
    if (!keywords) std::abort();
    return std::move(*keywords);
}

VariantSpace spaceOf(const std::vector<std::string>& texts) {
    DiagnosticList sink;
    std::optional<VariantSpace> space = VariantSpace::build(keywordsOf(texts), sink);
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

// 40 `shader_feature _ K` sets, fog and `_ M`: 2^43 declared variants. |range(0)| materials,
// material i enabling K(i mod 40) and K((7 i) mod 40): select, count and enumerate.
void selectTrillionPass(benchmark::State& state) {
    std::vector<std::string> texts = {"multi_compile_fog", "multi_compile _ M"};
    for (int i = 0; i < 40; ++i) texts.push_back("shader_feature _ K" + std::to_string(i));
    PassKeywords keywords = keywordsOf(texts);
    VariantSpace space = spaceOf(texts);
    std::vector<KeywordRequest> requests;
    for (int64_t i = 0; i < state.range(0); ++i) {
        requests.push_back({RequestKind::Material,
                            "M" + std::to_string(i),
                            {"K" + std::to_string(i % 40), "K" + std::to_string(7 * i % 40)}});
    }
    uint64_t shipped = 0;
    for (auto _ : state) {
        MaterialSelection selection = MaterialSelection::select(keywords, space, requests, false);
        shipped = selection.count();
        benchmark::DoNotOptimize(selection.enumerate().size());
    }
    state.counters["shipped"] = static_cast<double>(shipped);
}
BENCHMARK(selectTrillionPass)->Arg(5)->Arg(1000)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace varc::variants
