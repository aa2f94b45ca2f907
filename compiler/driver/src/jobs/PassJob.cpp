// SPDX-License-Identifier: Apache-2.0
#include "jobs/PassJob.h"

#include <xxhash.h>

#include <algorithm>
#include <map>

#include "varc/driver/CompileDriver.h"
#include "varc/driver/GlslLegacyPreamble.h"
#include "varc/driver/GlslangFrontend.h"
#include "varc/driver/GlslangLogParser.h"
#include "varc/driver/PassDefines.h"
#include "varc/frontend/EmptyMacroArguments.h"
#include "varc/frontend/HlslRewrites.h"
#include "varc/frontend/LegacyInstancedPropAccess.h"
#include "varc/frontend/MacroRedefinitions.h"
#include "varc/frontend/StagePruner.h"
#include "varc/variants/KeywordList.h"
#include "varc/variants/PassKeywords.h"

namespace varc::driver::detail {

shaderlab::ProgramLanguage languageOf(const PassJob& job) {
    return job.pass->pass->program->language;
}

// Identifies variant |variant| of pass job |job| across the build (for counting variants).
uint64_t variantId(size_t job, size_t variant) {
    return (static_cast<uint64_t>(job) << 32) | static_cast<uint64_t>(variant);
}

std::string contextOf(const PassJob& job, Stage stage, size_t variant) {
    const auto& table = job.pass->space->table();
    return std::string("in the ") + stageName(stage) + " stage of " +
           frontend::describePass(job.shader->ast, *job.pass->pass, job.pass->index) +
           ", keywords: " + variants::joinKeywords(table.namesOf(job.keys[variant]));
}

// The stages a pass compiles, from its #pragma vertex/fragment/...; reports missing entries.
bool collectStages(PassJob& job, DiagnosticSink& sink) {
    const variants::PassKeywords& kw = job.pass->keywords;
    bool glsl = languageOf(job) == shaderlab::ProgramLanguage::Glsl;
    auto entry = [&](const std::string& name) { return glsl ? std::string("main") : name; };
    if (!glsl && (kw.vertexEntry.empty() || kw.fragmentEntry.empty())) {
        sink.error(job.pass->pass->program->origin,
                   std::string("missing #pragma ") +
                       (kw.vertexEntry.empty() ? "vertex" : "fragment") + " in " +
                       frontend::describePass(job.shader->ast, *job.pass->pass, job.pass->index));
        return false;
    }
    job.stages.push_back({Stage::Vertex, entry(kw.vertexEntry)});
    job.stages.push_back({Stage::Fragment, entry(kw.fragmentEntry)});
    if (!kw.geometryEntry.empty()) job.stages.push_back({Stage::Geometry, entry(kw.geometryEntry)});
    if (!kw.hullEntry.empty()) job.stages.push_back({Stage::Hull, kw.hullEntry});
    if (!kw.domainEntry.empty()) job.stages.push_back({Stage::Domain, kw.domainEntry});
    return true;
}

void setUpProjections(PassJob& job, bool reachableCode) {
    const variants::KeywordTable& table = job.pass->space->table();
    std::optional<ObservedNames> own;
    const ObservedNames& names = job.observed ? *job.observed : own.emplace(job.text);
    variants::VariantKey formable;
    for (size_t k = 0; k < table.size(); ++k)
        if (names.mayPaste(table.name(k))) formable.set(k);
    auto text = std::make_shared<const ProjectionText>(job.text, table.names(), formable);
    // Stages whose preambles differ only in macros the text cannot name (the stage macros,
    // mostly) walk alike: they share one projection, and so its walks.
    std::map<std::string, std::shared_ptr<KeywordProjection>> byBase;
    std::map<std::string, size_t> firstWithBase;
    reachableCode = reachableCode && languageOf(job) != shaderlab::ProgramLanguage::Glsl;
    for (const auto& [stage, entry] : job.stages) {
        DefineContext context{job.pass->pass->lightMode(),
                              job.pass->keywords.target,
                              languageOf(job),
                              stage,
                              {},
                              job.pass->keywords.instancingOptions};
        std::vector<PredefinedMacro> macros = predefinedMacros(context);
        dropUnobservedMacros(macros, names);
        if (job.userDefines) job.userDefines->adopt(macros);
        std::string base = writePreamble(macros);
        if (languageOf(job) == shaderlab::ProgramLanguage::Glsl)
            base += legacyGlslPreamble(job.text, stage);
        // Reachability starts from the entry point: stages share a tree only if they share it.
        job.sameBaseAs.push_back(firstWithBase.emplace(base, job.sameBaseAs.size()).first->second);
        std::string entryPoint = reachableCode ? entry : std::string();
        std::shared_ptr<KeywordProjection>& projection = byBase[base + '\0' + entryPoint];
        if (!projection)
            projection = std::make_shared<KeywordProjection>(text, base, std::move(entryPoint));
        job.projections.push_back(projection);
    }
}

// The keywords of |variant| stage |stageIndex| is preprocessed with: its projection, or, when
// the projections leave out unreachable code, the largest projection of any stage with the same
// base preamble that agrees with the variant on every keyword this stage's projection depends on
// (it gives this stage the same program), so that stages share preprocessings as they did with
// every lookup counted.
variants::VariantKey stageKeyOf(const PassJob& job, size_t variant, size_t stageIndex) {
    const variants::VariantKey& key = job.keys[variant];
    if (job.projections.empty()) return key;
    KeywordProjection& own = *job.projections[stageIndex];
    variants::VariantKey kept;
    std::optional<variants::VariantKey> observed = own.observedOf(key, &kept);
    if (!observed) return key;
    if (!own.leavesOutUnreachable()) return *observed;
    variants::VariantKey best = *observed;
    for (size_t other = 0; other < job.projections.size(); ++other) {
        if (other == stageIndex || job.sameBaseAs[other] != job.sameBaseAs[stageIndex]) continue;
        std::optional<variants::VariantKey> theirs = job.projections[other]->observedOf(key);
        if (!theirs || (*theirs & kept) != *observed) continue;
        // Largest first, then the key order: stages seeing the same candidates pick the same.
        if (theirs->count() > best.count() || (theirs->count() == best.count() && *theirs < best))
            best = *theirs;
    }
    return best;
}

std::string preambleOf(const PassJob& job, size_t variant, size_t stageIndex) {
    const auto& [stage, entry] = job.stages[stageIndex];
    const variants::VariantKey key = stageKeyOf(job, variant, stageIndex);
    DefineContext context{job.pass->pass->lightMode(),
                          job.pass->keywords.target,
                          languageOf(job),
                          stage,
                          job.pass->space->table().namesOf(key),
                          job.pass->keywords.instancingOptions};
    std::vector<PredefinedMacro> macros = predefinedMacros(context);
    if (job.observed) dropUnobservedMacros(macros, *job.observed);
    if (job.userDefines) job.userDefines->adopt(macros);
    std::string preamble = writePreamble(macros);
    if (languageOf(job) == shaderlab::ProgramLanguage::Glsl) {
        preamble += legacyGlslPreamble(job.text, stage);
    }
    return preamble;
}

// glslang's preprocessing of |job|'s text: HLSL's does not depend on the stage beyond the
// preamble, GLSL's version and extension handling may.
std::string preprocessKeyOf(const PassJob& job, Stage stage, std::string preamble) {
    if (languageOf(job) != shaderlab::ProgramLanguage::Glsl) return preamble;
    return std::to_string(stageIndex(stage)) + "\n" + preamble;
}

ItemKey itemKeyOf(const std::string& preprocessKey, Stage stage, const std::string& entry) {
    std::string text = preprocessKey;
    text += '\0';
    text += std::to_string(stageIndex(stage));
    text += '\0';
    text += entry;
    XXH128_hash_t hash = XXH3_128bits(text.data(), text.size());
    return {hash.low64, hash.high64};
}

StageResult preprocessStage(const PassJob& job, Stage stage, const std::string& entry,
                            const std::string& preamble, const includes::SourceMap& sourceMap) {
    bool hlsl = languageOf(job) != shaderlab::ProgramLanguage::Glsl;
    std::string text = job.text;
    // A one-parameter macro called with an empty argument (or with `##`, as for Unity's older
    // preprocessor): C99 and Unity take it, glslang stops in every variant that reaches the
    // call. Expanded once for the pass, before any variant's preprocessing, so no variant pays
    // for a failing one (the result depends on the text alone, whatever the thread order).
    if (hlsl)
        text =
            job.rewrites->apply("empty macro arguments", text, frontend::expandEmptyMacroArguments);
    PreprocessOutput pre = preprocessProgram({text, preamble, languageOf(job), stage, entry});
    if (!pre.ok && hlsl && pre.log.find("hexadecimal literal too big") != std::string::npos) {
        // The DirectX compilers keep the low 32 bits of such a literal; so does varc.
        text = job.rewrites->apply("wide hex literals", text, frontend::truncateWideHexLiterals);
        pre = preprocessProgram({text, preamble, languageOf(job), stage, entry});
    }
    // Empty macro arguments again, in the text with its hex literals truncated.
    if (!pre.ok && hlsl &&
        (pre.log.find("Too few args in Macro") != std::string::npos ||
         pre.log.find("unexpected '#'") != std::string::npos)) {
        const std::string& expanded =
            job.rewrites->apply("empty macro arguments", text, frontend::expandEmptyMacroArguments);
        if (expanded != text) {
            text = expanded;
            pre = preprocessProgram({text, preamble, languageOf(job), stage, entry});
        }
    }
    // Unity 5.6's one-argument UNITY_ACCESS_INSTANCED_PROP(name): given a block name, as the
    // two-argument form UnityInstancing.cginc defines (only when the call stopped glslang).
    if (!pre.ok && hlsl && pre.log.find("Too few args in Macro") != std::string::npos) {
        const std::string& expanded =
            job.rewrites->apply("one-argument instanced property access", text,
                                frontend::expandLegacyInstancedPropAccess);
        if (expanded != text) {
            text = expanded;
            pre = preprocessProgram({text, preamble, languageOf(job), stage, entry});
        }
    }
    // Unity's HLSL compilers warn about a macro redefined with another value and take the new
    // one; glslang stops. varc warns and #undefs before each redefinition (bounded: each round
    // names at least one macro not handled before).
    std::vector<Diagnostic> redefinitions;
    std::vector<std::string> names;
    for (int round = 0; round < 16 && !pre.ok && hlsl; ++round) {
        std::vector<std::string> found = frontend::redefinedMacros(pre.log);
        size_t before = names.size();
        for (std::string& name : found) {
            if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
        }
        if (names.size() == before) break;
        for (Diagnostic& diagnostic : parseGlslangLog(pre.log, sourceMap)) {
            std::vector<std::string> named = frontend::redefinedMacros(diagnostic.message);
            if (named.empty()) continue;
            diagnostic.severity = Severity::Warning;
            diagnostic.message = "macro '" + named.front() +
                                 "' redefined with a different value; the later definition "
                                 "wins, as with Unity's HLSL compilers";
            redefinitions.push_back(std::move(diagnostic));
        }
        pre = preprocessProgram({frontend::undefineBeforeRedefinitions(text, names), preamble,
                                 languageOf(job), stage, entry});
    }
    StageResult result;
    result.diagnostics = std::move(redefinitions);
    for (Diagnostic& diagnostic : parseGlslangLog(pre.log, sourceMap)) {
        result.diagnostics.push_back(std::move(diagnostic));
    }
    result.ok = pre.ok;
    result.text = std::move(pre.text);
    return result;
}

std::string pruneStage(const PassJob& job, const std::string& preprocessed,
                       const std::string& entry, const BuildOptions& options, bool& pruned) {
    pruned = false;
    if (!options.pruneStages) return preprocessed;
    frontend::ShaderDialect dialect = languageOf(job) == shaderlab::ProgramLanguage::Glsl
                                          ? frontend::ShaderDialect::Glsl
                                          : frontend::ShaderDialect::Hlsl;
    frontend::PruneResult result = frontend::pruneToEntryPoint(preprocessed, entry, dialect);
    pruned = result.pruned;
    return std::move(result.text);
}

}  // namespace varc::driver::detail
