// SPDX-License-Identifier: Apache-2.0
#include "jobs/ProgramCompiler.h"

#include <algorithm>
#include <cctype>
#include <ctime>
#include <optional>
#include <string>

#include "varc/core/JoinWords.h"
#include "varc/driver/GlslVersionDirective.h"
#include "varc/driver/GlslangFrontend.h"
#include "varc/driver/GlslangLogParser.h"
#include "varc/driver/SpirvImageOffsets.h"
#include "varc/driver/SpirvMatrixMath.h"
#include "varc/driver/SpirvOptimizer.h"
#include "varc/driver/SpirvReflection.h"
#include "varc/frontend/CbufferRedeclarations.h"
#include "varc/frontend/EntryPointCheck.h"
#include "varc/frontend/HlslRewrites.h"
#include "varc/frontend/LoopVariableScope.h"
#include "varc/frontend/OpaqueStructMembers.h"
#include "varc/variants/PassKeywords.h"

namespace varc::driver::detail {

namespace {

// The whitespace-separated words of |text| ("float4\n  x" -> {"float4", "x"}).
std::vector<std::string> splitWords(std::string_view text) {
    std::vector<std::string> words;
    size_t i = 0;
    while (i < text.size()) {
        while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
        size_t begin = i;
        while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i]))) ++i;
        if (i > begin) words.emplace_back(text.substr(begin, i - begin));
    }
    return words;
}

// glslang's output for one program text: compiled, then (when it compiled) validated as it
// stands, optimised and validated again.
struct Attempt {
    CompileOutput compiled;
    SpirvResult optimized;
    std::optional<std::string> invalid;   // the validator's message, on glslang's output or ours
    bool invalidInput = false;            // |invalid| is about glslang's output
    std::optional<std::string> crashed;   // the optimiser worker's fate when it gave no outcome
    std::optional<std::string> fellBack;  // why legalisation alone replaced -O/-Os
};

// The optimisation recipe |level| names, for messages.
std::string recipeName(OptimizationLevel level) {
    switch (level) {
        case OptimizationLevel::None:
            return "legalisation (-O0)";
        case OptimizationLevel::Performance:
            return "-O recipe";
        case OptimizationLevel::Size:
            return "-Os recipe";
    }
    return "optimiser";
}

// validateAndOptimize of |spirv|, in this process or in a worker of |options|' pool. When a
// worker dies on -O/-Os, legalisation alone is a safe fallback (every module needs it, and it
// is a subset of the passes that crashed): it is tried once, and the attempt says why.
void optimizeInto(Attempt& attempt, const std::vector<uint32_t>& spirv,
                  const BuildOptions& options) {
    OptimizationLevel level = options.optimization;
    if (!options.optimizerPool) {
        OptimizeOutcome outcome = validateAndOptimize(spirv, level);
        attempt.invalid = std::move(outcome.invalidInput);
        attempt.invalidInput = attempt.invalid.has_value();
        attempt.optimized = std::move(outcome.optimized);
        return;
    }
    IsolatedOutcome isolated = options.optimizerPool->optimize(spirv, level);
    if (!isolated.outcome && level != OptimizationLevel::None) {
        std::string first = "the SPIR-V optimiser worker " + isolated.failure + " running the " +
                            recipeName(level) + " on this program";
        isolated = options.optimizerPool->optimize(spirv, OptimizationLevel::None);
        if (isolated.outcome)
            attempt.fellBack = first;
        else
            attempt.crashed = first + ", and " + isolated.failure + " again on legalisation alone";
    } else if (!isolated.outcome) {
        attempt.crashed = "the SPIR-V optimiser worker " + isolated.failure + " running " +
                          recipeName(level) + " on this program";
    }
    if (!isolated.outcome) return;
    attempt.invalid = std::move(isolated.outcome->invalidInput);
    attempt.invalidInput = attempt.invalid.has_value();
    attempt.optimized = std::move(isolated.outcome->optimized);
}

Attempt compileAndValidate(const StageProgram& program, const std::string& text,
                           const BuildOptions& options) {
    Attempt attempt;
    // glslang's preprocessed output keeps the lines above `#version`; the compile needs it first.
    const std::string source =
        program.language == shaderlab::ProgramLanguage::Glsl ? hoistGlslVersion(text) : text;
    attempt.compiled =
        compileProgram({source, "", program.language, program.stage, program.entryPoint});
    if (!attempt.compiled.ok) return attempt;
    attempt.compiled.spirv = splitMatrixExtendedMath(attempt.compiled.spirv);
    optimizeInto(attempt, attempt.compiled.spirv, options);
    if (attempt.crashed || attempt.invalid || !attempt.optimized.ok) return attempt;
    attempt.optimized.spirv = markConstantImageOffsets(attempt.optimized.spirv);
    attempt.invalid = validateSpirv(attempt.optimized.spirv);
    return attempt;
}

// Whether the validator refused OpAny or OpAll on a scalar: glslang's `any(x)` / `all(x)` of a
// scalar, which the DirectX compilers read as `x != 0`.
bool refusedScalarAnyAll(const Attempt& attempt) {
    if (!attempt.invalid) return false;
    const std::string& message = *attempt.invalid;
    return message.find("Expected operand to be vector bool: Any") != std::string::npos ||
           message.find("Expected operand to be vector bool: All") != std::string::npos;
}

// Whether glslang refused |program|, or made invalid SPIR-V of it, for a construct Unity's HLSL
// compilers accept and rewriteHlslForGlslang makes explicit. Only such programs are rewritten,
// so every program glslang compiles as written compiles exactly as before.
bool needsHlslRewrite(const StageProgram& program, const Attempt& attempt) {
    if (program.language == shaderlab::ProgramLanguage::Glsl) return false;
    if (attempt.invalid) {
        return attempt.invalid->find("OpTypeStruct must not contain an opaque type") !=
                   std::string::npos ||
               refusedScalarAnyAll(attempt);
    }
    const std::string& log = attempt.compiled.log;
    return !attempt.compiled.ok &&
           (log.find("condition must be a scalar integer expression") != std::string::npos ||
            log.find("can't modify a uniform") != std::string::npos ||
            log.find("Missing functionality: matrix swizzle") != std::string::npos ||
            log.find("only simple assignment to non-simple matrix swizzle") != std::string::npos ||
            log.find("hexadecimal literal too big") != std::string::npos ||
            log.find("'member type' : Expected") != std::string::npos ||
            log.find("unknown variable") != std::string::npos ||
            log.find("no matching overloaded function found") != std::string::npos);
}

// The names glslang quoted before |message| in |log|, each once: for
// "' : no matching overloaded function found", "ERROR: 3:85: 'Linear01Depth' : no matching
// overloaded function found" -> {"Linear01Depth"}.
std::vector<std::string> quotedNames(const std::string& log, std::string_view message) {
    std::vector<std::string> names;
    for (size_t at = log.find(message); at != std::string::npos; at = log.find(message, at + 1)) {
        size_t open = log.rfind('\'', at - 1);
        if (open == std::string::npos) continue;
        std::string name = log.substr(open + 1, at - open - 1);
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
    return names;
}

// Appends the names in |more| that |names| does not hold yet.
void appendNew(std::vector<std::string>& names, const std::vector<std::string>& more) {
    for (const std::string& name : more) {
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
}

// At most this many rewrites of one program (each one a glslang compile).
constexpr int kMaxRewriteRounds = 4;

// The functions glslang found no overload for, and the variables it did not know.
std::vector<std::string> unmatchedCalls(const std::string& log) {
    return quotedNames(log, "' : no matching overloaded function found");
}
std::vector<std::string> unknownVariables(const std::string& log) {
    return quotedNames(log, "' : unknown variable");
}

// Compiles |text|, then, while glslang's log asks for them, the HLSL rewrites of it.
// glslang's HLSL parser stops at the first error, so what one rewrite fixes may uncover the
// next (a call needing a cast, then a loop variable used after its loop): each round
// rewrites the original text with everything the logs so far asked for. Either way the last
// program's outcome is the one to report: its errors are the ones left once the constructs
// Unity accepts are accepted.
Attempt compileWithRewrites(const StageProgram& program, const std::string& text,
                            const BuildOptions& options) {
    Attempt attempt = compileAndValidate(program, text, options);
    std::vector<std::string> calls, unknownNames;
    bool scalarAnyAll = false;
    std::string previous = text;
    for (int round = 0; round < kMaxRewriteRounds && needsHlslRewrite(program, attempt); ++round) {
        appendNew(calls, unmatchedCalls(attempt.compiled.log));
        appendNew(unknownNames, unknownVariables(attempt.compiled.log));
        scalarAnyAll = scalarAnyAll || refusedScalarAnyAll(attempt);
        std::string rewritten = frontend::hoistLoopVariables(
            frontend::rewriteHlslForGlslang(text, calls, scalarAnyAll), unknownNames);
        if (rewritten == previous) break;
        attempt = compileAndValidate(program, rewritten, options);
        previous = std::move(rewritten);
    }
    // A texture inside a struct, which the texture-sampler transform leaves a plain image: once
    // more with the member declared as the combined sampler the global texture became.
    if (program.language != shaderlab::ProgramLanguage::Glsl && attempt.invalid &&
        attempt.invalidInput) {
        std::string combined = frontend::combineStructTextureMembers(previous);
        if (combined != previous) {
            Attempt retry = compileAndValidate(program, combined, options);
            if (retry.compiled.ok && !(retry.invalid && retry.invalidInput))
                attempt = std::move(retry);
        }
    }
    return attempt;
}

// What glslang's HLSL front end would crash on, as a glslang log line ("ERROR: file:line: ..."),
// or nullopt: an unnamed entry-point parameter (KhronosGroup/glslang#4389), a global redeclaring
// a cbuffer member with another type (found by the `build` fuzz target).
std::optional<std::string> refusalBeforeGlslang(const StageProgram& program) {
    if (program.language == shaderlab::ProgramLanguage::Glsl) return std::nullopt;
    if (auto unnamed = frontend::findUnnamedEntryParameter(program.text, program.entryPoint)) {
        std::string written = joinWords(splitWords(unnamed->text));
        return "ERROR: " + std::to_string(unnamed->file) + ":" + std::to_string(unnamed->line) +
               ": '" + std::string(program.entryPoint) + "' : entry-point parameter " +
               std::to_string(unnamed->index) + " ('" + written +
               "') has no name; give it one (glslang cannot compile it)\n";
    }
    if (auto again = frontend::findCbufferRedeclaration(program.text)) {
        // glslang's format: the parser appends the quoted name to the message.
        return "ERROR: " + std::to_string(again->file) + ":" + std::to_string(again->line) + ": '" +
               again->name + "' : type differs from " +
               (again->cbufferName.empty() ? "an earlier declaration"
                                           : "the built-in cbuffer " + again->cbufferName) +
               "'s (" + again->memberType + ", here " + again->type +
               "); remove this declaration or make it " + again->memberType + ":\n";
    }
    return std::nullopt;
}

// The error for a module the validator refused before optimising: for HLSL with a texture or
// sampler inside a struct (what glslang's texture-sampler transform cannot combine), one at that
// member naming the construct; otherwise the validator's own message at the program's block.
std::vector<Diagnostic> invalidModuleDiagnostics(const StageProgram& program,
                                                 const std::string& invalid,
                                                 const includes::SourceMap& sourceMap) {
    if (program.language != shaderlab::ProgramLanguage::Glsl) {
        if (auto member = frontend::findOpaqueStructMember(program.text)) {
            // Through glslang's log format for the mapping to the user's file:line:col.
            std::vector<Diagnostic> found = parseGlslangLog(
                "ERROR: " + std::to_string(member->file) + ":" + std::to_string(member->line) +
                    ": '" + member->member + "' : opaque struct member\n",
                sourceMap);
            if (found.size() == 1 && found[0].location.isKnown()) {
                found[0].message = "the " + member->type + " '" + member->member +
                                   "' is a member of struct '" + member->structName +
                                   "', which glslang cannot compile for Vulkan (its "
                                   "texture-sampler transform leaves a struct member a plain "
                                   "image); pass the texture and its sampler as separate "
                                   "parameters instead";
                return found;
            }
        }
    }
    return {{Severity::Error,
             program.origin,
             "glslang's SPIR-V is invalid (refused before optimising): " + invalid,
             {}}};
}

}  // namespace

CompiledSource compileStageProgram(const StageProgram& program, const BuildOptions& options,
                                   const ProgramCache* cache, const includes::SourceMap& sourceMap,
                                   const std::function<void(const Status&)>& onCacheFailure) {
    const bool vertex = program.stage == Stage::Vertex;
    CompiledSource result;
    auto fail = [&](std::string message) {
        result.diagnostics.push_back({Severity::Error, program.origin, std::move(message), {}});
        return result;
    };
    // Reflection needs the debug names; what ships goes without them unless
    // BuildOptions::debugNames. The cache keeps both forms.
    std::optional<ProgramCacheKey> key;
    if (cache) {
        key = cache->keyOf({options.optimization, program.language, program.stage,
                            program.entryPoint, program.text});
        if (std::optional<CachedProgram> hit = cache->load(*key)) {
            if (auto reflection = reflectSpirv(hit->spirv, hit->semantics, vertex)) {
                result.ok = result.fromCache = true;
                result.diagnostics = parseGlslangLog(hit->log, sourceMap);
                result.spirv = std::move(options.debugNames ? hit->spirv : hit->stripped);
                result.reflection = std::move(*reflection);
                return result;
            }
        }
    }
    if (std::optional<std::string> refusal = refusalBeforeGlslang(program)) {
        result.diagnostics = parseGlslangLog(*refusal, sourceMap);
        return result;
    }
    std::string text = program.language == shaderlab::ProgramLanguage::Glsl
                           ? std::string(program.text)
                           : frontend::fixFrontFaceParameterTypes(program.text);
    Attempt attempt = compileWithRewrites(program, text, options);
    CompileOutput& compiled = attempt.compiled;
    result.diagnostics = parseGlslangLog(compiled.log, sourceMap);
    // glslang's link and "missing functionality" messages name no line: they belong to the
    // program, so they point at its block (and get the stage and keywords note like the rest).
    for (Diagnostic& diagnostic : result.diagnostics) {
        if (!diagnostic.location.isKnown()) diagnostic.location = program.origin;
    }
    if (!compiled.ok) return result;
    if (attempt.crashed) return fail(*attempt.crashed + " (please report it with this shader)");
    if (attempt.invalid && attempt.invalidInput) {
        for (Diagnostic& refusal : invalidModuleDiagnostics(program, *attempt.invalid, sourceMap))
            result.diagnostics.push_back(std::move(refusal));
        return result;
    }
    SpirvResult& optimized = attempt.optimized;
    if (!optimized.ok) return fail("SPIR-V optimisation failed: " + optimized.message);
    if (attempt.invalid) return fail("generated SPIR-V is invalid: " + *attempt.invalid);
    if (attempt.fellBack) {
        result.diagnostics.push_back(
            {Severity::Warning,
             program.origin,
             *attempt.fellBack + "; built it with legalisation alone (unoptimised)",
             {}});
    }
    std::optional<SemanticsByLocation> semantics = hlslSemantics(compiled.spirv);
    std::optional<pack::ProgramReflection> reflection;
    if (semantics) reflection = reflectSpirv(optimized.spirv, *semantics, vertex);
    if (!reflection) return fail("cannot reflect the generated SPIR-V");
    SpirvResult stripped = stripDebugInfo(optimized.spirv);
    if (!stripped.ok) return fail("cannot strip SPIR-V debug names: " + stripped.message);
    // A fallback's module is not what the cache key promises (-O/-Os): it is not stored, so the
    // next build tries the recipe again and warns again.
    if (cache && !attempt.fellBack) {
        onCacheFailure(cache->store(
            *key, {optimized.spirv, stripped.spirv, std::move(*semantics), compiled.log}));
    }
    result.ok = true;
    result.spirv = std::move(options.debugNames ? optimized.spirv : stripped.spirv);
    result.reflection = std::move(*reflection);
    return result;
}

double threadCpuSeconds() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

double processCpuSeconds() {
    timespec now{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

}  // namespace varc::driver::detail
