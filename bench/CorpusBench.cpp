// SPDX-License-Identifier: Apache-2.0
// The compatibility corpus (../shared/compat, read in place) built the two ways issue #10
// compares, in one run:
//   - varc: every variant of every corpus shader that builds, in-process, on a worker pool;
//   - the yardstick: one glslangValidator process per distinct program and stage, where
//     "distinct" is what a careful script could dedupe without a preprocessor of its own: the
//     same text with the same predefined macros (those the text can observe) for the same stage
//     and entry point. varc's own dedup after preprocessing and pruning goes further.
// Shaders whose passes have at most 2000 variants take part (all but a few; see corpus()).
// Run: ./build/bench/varc_bench_corpus. Results go in docs/PERFORMANCE.md.
#include <benchmark/benchmark.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "BenchInputs.h"
#include "varc/core/Diagnostic.h"
#include "varc/driver/CompileDriver.h"
#include "varc/driver/GlslLegacyPreamble.h"
#include "varc/driver/ObservedDefines.h"
#include "varc/driver/PassDefines.h"
#include "varc/frontend/ShaderLoader.h"
#include "varc/includes/FileSystem.h"

namespace varc {
namespace {

// The corpus shaders varc builds (those it refuses are in docs/COMPATIBILITY.md), loaded once.
// Passes of at most 2000 variants (as the sanitizer job's corpus run): the few larger ones
// (MToon's 98 862) would make the glslangValidator side run for hours.
bench::BenchInputs& corpus() {
    static bench::BenchInputs* loaded = [] {
        auto* in = new bench::BenchInputs;
        bench::addBuildableCorpus(*in, 2000, 2);
        return in;
    }();
    return *loaded;
}

void BM_VarcCorpusBuild(benchmark::State& state) {
    bench::BenchInputs& in = corpus();
    if (in.shaders.empty()) return state.SkipWithError("no corpus (../shared/compat) shader built");
    driver::BuildOptions options;
    options.jobs = static_cast<unsigned>(state.range(0));
    std::optional<driver::BuildOutput> output;
    for (auto _ : state) {
        DiagnosticList diagnostics;
        output = driver::buildPrograms(in.shaders, in.sourceMap, options, diagnostics);
        if (!output) return state.SkipWithError("build failed");
    }
    state.counters["files"] = static_cast<double>(in.corpusFiles);
    state.counters["variants"] = static_cast<double>(in.variants);
    state.counters["distinct"] = static_cast<double>(output->compiledSources);
    state.counters["modules"] = static_cast<double>(output->programs.size());
}
BENCHMARK(BM_VarcCorpusBuild)
    ->ArgNames({"jobs"})
    ->Arg(2)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

const char* validatorStage(Stage stage) {
    switch (stage) {
        case Stage::Vertex: return "vert";
        case Stage::Fragment: return "frag";
        case Stage::Geometry: return "geom";
        case Stage::Hull: return "tesc";
        case Stage::Domain: return "tese";
    }
    return "vert";
}

// One program text per distinct (text, observed predefined macros, stage, entry point) of every
// variant and stage of |pass|, appended to |programs| as (stage, entry, source).
struct ValidatorProgram {
    Stage stage;
    bool glsl;
    std::string entry;
    std::string source;
    bool operator<(const ValidatorProgram& o) const {
        return std::tie(stage, glsl, entry, source) < std::tie(o.stage, o.glsl, o.entry, o.source);
    }
};

void collectPrograms(const frontend::LoadedPass& pass, std::set<ValidatorProgram>& programs) {
    bool glsl = pass.pass->program->language == shaderlab::ProgramLanguage::Glsl;
    driver::ObservedNames observed(pass.source.text);
    std::vector<std::pair<Stage, std::string>> stages = {
        {Stage::Vertex, pass.keywords.vertexEntry}, {Stage::Fragment, pass.keywords.fragmentEntry}};
    if (!pass.keywords.geometryEntry.empty()) stages.push_back({Stage::Geometry, pass.keywords.geometryEntry});
    if (!pass.keywords.hullEntry.empty()) stages.push_back({Stage::Hull, pass.keywords.hullEntry});
    if (!pass.keywords.domainEntry.empty()) stages.push_back({Stage::Domain, pass.keywords.domainEntry});
    pass.space->forEach([&](const variants::VariantKey& key) {
        std::vector<std::string> keywords = pass.space->table().namesOf(key);
        for (const auto& [stage, entry] : stages) {
            driver::DefineContext context{pass.pass->lightMode(), pass.keywords.target,
                                          pass.pass->program->language, stage, keywords,
                                          pass.keywords.instancingOptions};
            std::vector<driver::PredefinedMacro> macros = driver::predefinedMacros(context);
            driver::dropUnobservedMacros(macros, observed);
            std::string source = driver::writePreamble(macros);
            if (glsl) {
                source =
                    "#version 140\n" + source + driver::legacyGlslPreamble(pass.source.text, stage);
            }
            programs.insert({stage, glsl, glsl ? "main" : entry, source + pass.source.text});
        }
        return true;
    });
}

void BM_GlslangValidatorPerDistinctProgram(benchmark::State& state) {
    bench::BenchInputs& in = corpus();
    if (in.shaders.empty()) return state.SkipWithError("no corpus (../shared/compat) shader built");
    std::set<ValidatorProgram> programs;
    for (const frontend::LoadedShader& shader : in.shaders) {
        for (const frontend::LoadedPass& pass : shader.passes) collectPrograms(pass, programs);
    }
    std::string dir = std::filesystem::temp_directory_path() /
                      ("varc-bench-corpus-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    size_t failures = 0;
    for (auto _ : state) {
        for (const ValidatorProgram& program : programs) {
            std::string path = dir + (program.glsl ? "/program.glsl" : "/program.hlsl");
            std::ofstream(path) << program.source;
            std::string command = "glslangValidator -V --quiet --auto-map-bindings "
                                  "--auto-map-locations --target-env vulkan1.0 -S " +
                                  std::string(validatorStage(program.stage)) + " ";
            command += program.glsl ? "-R " : "-D --hlsl-dx9-compatible -e " + program.entry + " ";
            command += path + " -o " + dir + "/program.spv > /dev/null 2>&1";
            if (std::system(command.c_str()) != 0) ++failures;
        }
    }
    std::filesystem::remove_all(dir);
    state.counters["processes"] = static_cast<double>(programs.size());
    // glslangValidator lacks varc's tolerances (rewrites, implicit includes), so some fail; a
    // failing process costs about as much as a successful one.
    state.counters["failures"] = static_cast<double>(failures);
}
BENCHMARK(BM_GlslangValidatorPerDistinctProgram)
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
}  // namespace varc
