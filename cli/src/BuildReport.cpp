// SPDX-License-Identifier: Apache-2.0
// The staged summary `varc build` prints.
#include "varc/cli/BuildReport.h"

#include <iomanip>
#include <ostream>
#include <sstream>

#include "varc/cli/VariantReport.h"
#include "varc/core/JoinWords.h"
#include "varc/variants/PassKeywords.h"

namespace varc::cli {

namespace {

using Json = nlohmann::ordered_json;

// "vertex 2, fragment 1" for the stages a pass compiles.
std::string stageCounts(const std::array<size_t, kStageCount>& counts) {
    std::string text;
    for (Stage stage : kStages) {
        size_t count = counts[stageIndex(stage)];
        if (count == 0) continue;
        if (!text.empty()) text += ", ";
        text += std::string(stageName(stage)) + " " + std::to_string(count);
    }
    return text;
}

StageMask compiledStages(const driver::CompiledPass& pass) {
    StageMask stages = 0;
    for (Stage stage : kStages) {
        if (pass.stats.distinctModules[stageIndex(stage)] > 0) stages |= stageBit(stage);
    }
    return stages;
}

// For each declared set with keywords: the stages it turned out not to change.
std::vector<std::pair<std::string, std::vector<std::string>>> unaffectedStages(
    const frontend::LoadedPass& loaded, const driver::CompiledPass& pass) {
    std::vector<std::pair<std::string, std::vector<std::string>>> result;
    StageMask stages = compiledStages(pass);
    for (size_t i = 0; i < pass.setStageEffects.size(); ++i) {
        std::vector<std::string> unaffected;
        for (Stage stage : kStages) {
            if (hasStage(stages, stage) && !hasStage(pass.setStageEffects[i], stage)) {
                unaffected.push_back(stageName(stage));
            }
        }
        std::string keywords;
        for (const std::string& keyword : loaded.keywords.sets[i].keywords) {
            if (!keyword.empty()) keywords += (keywords.empty() ? "" : " ") + keyword;
        }
        if (!unaffected.empty() && !keywords.empty()) result.push_back({keywords, unaffected});
    }
    return result;
}

std::string kibibytes(uint64_t bytes) {
    std::ostringstream out;
    out << std::fixed << std::setprecision(1) << static_cast<double>(bytes) / 1024.0 << " KiB";
    return out.str();
}

// "Cache level 1 (file:/c): 12 hits, 3 misses; read 4.0 KiB, wrote 1.0 KiB" (+ damaged,
// errors and timeouts, failed).
void printCacheLevel(size_t index, const cache::CacheLevelStats& level, std::ostream& out) {
    out << "Cache level " << index + 1 << " (" << level.name << "): " << level.hits << " hits, "
        << level.misses << " misses";
    if (level.damaged) out << " (" << level.damaged << " damaged)";
    out << "; read " << kibibytes(level.bytesRead) << ", wrote " << kibibytes(level.bytesWritten);
    if (level.errors || level.timeouts)
        out << "; " << level.errors << " errors, " << level.timeouts << " timeouts";
    if (level.failed) out << "; failed, not used for the rest of the build";
    out << "\n";
}

Json cacheLevelJson(const cache::CacheLevelStats& level) {
    return {{"url", level.name},
            {"hits", level.hits},
            {"misses", level.misses},
            {"damaged", level.damaged},
            {"writes", level.writes},
            {"bytes_read", level.bytesRead},
            {"bytes_written", level.bytesWritten},
            {"errors", level.errors},
            {"timeouts", level.timeouts},
            {"failed", level.failed}};
}

}  // namespace

void printBuildReport(const std::vector<frontend::LoadedShader>& shaders,
                      const driver::BuildOutput& build, const PackSizes& sizes, double seconds,
                      std::ostream& out) {
    uint64_t variants = 0;
    for (const driver::CompiledPass& pass : build.passes) {
        const frontend::LoadedShader& shader = shaders[pass.shaderIndex];
        const frontend::LoadedPass& loaded = shader.passes[pass.passIndex];
        variants += pass.stats.variants;
        out << "Compiling " << frontend::describePass(shader.ast, *loaded.pass, loaded.index)
            << "\n"
            << "    Full variant space:          " << pass.stats.declaredVariants << "\n"
            << "    After skips and rules:       " << loaded.space->count() << "\n";
        if (loaded.plan) {
            out << "    After materials:             " << loaded.plan->counts.materials << "\n"
                << "    After settings stripping:    " << loaded.plan->counts.settings << "\n"
                << "    After strip rules:           " << loaded.plan->counts.rules << "\n";
        }
        out << "    Distinct programs:           " << stageCounts(pass.stats.distinctSources)
            << "\n"
            << "    Compiled SPIR-V modules:     " << stageCounts(pass.stats.distinctModules)
            << "\n";
        for (const auto& [keywords, stages] : unaffectedStages(loaded, pass)) {
            out << "    Does not affect " << joinWords(stages, ", ") << ": " << keywords << "\n";
        }
    }
    out << "Built " << variants << " variants from " << build.compiledSources
        << " distinct programs (" << build.preprocessedPrograms << " preprocessed";
    if (build.cachedSources + build.cachedStageSources > 0) {
        out << "; cache: " << build.cachedStageSources << " sources, " << build.cachedSources
            << " programs";
    }
    out << ") into " << sizes.modules << " SPIR-V modules in " << std::fixed << std::setprecision(2)
        << seconds << " s; raw SPIR-V " << kibibytes(sizes.rawSpirvBytes) << ", unique "
        << kibibytes(sizes.uniqueSpirvBytes) << ", pack " << kibibytes(sizes.packBytes) << "\n";
    for (size_t i = 0; i < build.cacheLevels.size(); ++i)
        printCacheLevel(i, build.cacheLevels[i], out);
}

Json buildReportJson(const std::vector<frontend::LoadedShader>& shaders,
                     const driver::BuildOutput& build, const PackSizes& sizes, double seconds) {
    Json passes = Json::array();
    for (const driver::CompiledPass& pass : build.passes) {
        const frontend::LoadedShader& shader = shaders[pass.shaderIndex];
        const frontend::LoadedPass& loaded = shader.passes[pass.passIndex];
        Json sources = Json::object(), programs = Json::object(), unaffected = Json::object();
        for (Stage stage : kStages) {
            size_t slot = stageIndex(stage);
            if (pass.stats.distinctModules[slot] == 0) continue;
            const char* name = stageName(stage);
            sources[name] = pass.stats.distinctSources[slot];
            programs[name] = pass.stats.distinctModules[slot];
        }
        for (const auto& [keywords, stages] : unaffectedStages(loaded, pass))
            unaffected[keywords] = stages;
        passes.push_back({{"shader", shader.ast.name},
                          {"pass", loaded.index},
                          {"lightmode", loaded.pass->lightMode()},
                          {"declared", pass.stats.declaredVariants},
                          {"variants", pass.stats.variants},
                          {"sources", sources},
                          {"programs", programs},
                          {"unaffected", unaffected}});
        if (loaded.plan) passes.back()["stages"] = stagesJson(loaded.plan->counts);
    }
    Json cacheJson = Json::array();
    for (const cache::CacheLevelStats& level : build.cacheLevels)
        cacheJson.push_back(cacheLevelJson(level));
    return {{"passes", passes},
            {"programs", sizes.modules},
            {"compiled_sources", build.compiledSources},
            {"preprocessed", build.preprocessedPrograms},
            {"keyword_projections", build.keywordProjections},
            {"projection_walks", build.projectionWalks},
            {"unprojected_stages", build.unprojectedStages},
            {"frontend_seconds", build.frontendSeconds},
            {"cached_sources", build.cachedSources},
            {"cached_stage_sources", build.cachedStageSources},
            // Programs glslang compiled in this build (0 when the cache served them all).
            {"compiled_programs", build.compiledSources - build.cachedSources},
            {"cache", cacheJson},
            {"bytes",
             {{"raw", sizes.rawSpirvBytes},
              {"unique", sizes.uniqueSpirvBytes},
              {"pack", sizes.packBytes}}},
            {"seconds", seconds}};
}

}  // namespace varc::cli
