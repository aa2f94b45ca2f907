// SPDX-License-Identifier: Apache-2.0
// Compiles every variant of every loaded pass: each distinct stage program once, in parallel.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "varc/build/SpirvOptimizer.h"
#include "varc/core/Diagnostic.h"
#include "varc/frontend/ShaderLoader.h"
#include "varc/includes/SourceMap.h"
#include "varc/pack/ProgramReflection.h"
#include "varc/variants/VariantKey.h"

namespace varc::compiler {

// Stage slots in variant tables: vertex, fragment, geometry, hull, domain.
inline constexpr size_t kStageCount = 5;
inline constexpr uint32_t kNoProgram = 0xffffffffu;
// Slot of a single variants::StageBits bit; kStageCount for anything else.
size_t stageSlot(uint32_t stageBit);
uint32_t stageBitOfSlot(size_t slot);
const char* stageName(uint32_t stageBit);  // "vertex", "fragment", ...

struct BuildOptions {
    OptimizationLevel optimization = OptimizationLevel::Performance;
    unsigned jobs = 0;         // 0 = the machine's hardware concurrency
    bool keepGoing = false;    // compile everything even after errors, to report them all
    bool pruneStages = true;   // prune each stage to what its entry point reaches before dedup
    bool debugNames = false;   // keep OpName/OpMemberName/OpSource in the shipped SPIR-V
    // Drop the defines a pass's text cannot observe before preprocessing (ObservedDefines.h), so
    // variants differing only in them share one preprocessing. Off only to check that it
    // changes no program.
    bool shareUnobservedDefines = true;
    // A ProgramCache folder: programs found there are not compiled again, programs compiled are
    // stored there. "" = no cache.
    std::string cacheDirectory;
    // Called from worker threads after each distinct program compiles: (done, total). Must be
    // thread-safe; may be empty.
    std::function<void(size_t, size_t)> progress;
};

// One optimised, validated SPIR-V module, shared by every variant whose stage compiles to it.
struct CompiledProgram {
    uint32_t stage = 0;  // variants::StageBits bit
    std::string entryPoint;
    std::vector<uint32_t> spirv;
    pack::ProgramReflection reflection;
    size_t shaderIndex = 0, passIndex = 0;  // where it was first used (for source info)
};

struct CompiledVariant {
    variants::VariantKey key;
    std::array<uint32_t, kStageCount> programs{kNoProgram, kNoProgram, kNoProgram, kNoProgram,
                                               kNoProgram};
    friend bool operator==(const CompiledVariant&, const CompiledVariant&) = default;
};

// Per pass: the staged counts of `varc build`'s summary.
struct PassBuildStats {
    uint64_t declaredVariants = 0;  // full product of the keyword sets
    uint64_t variants = 0;          // after skip_variants and shortcut rules
    std::array<size_t, kStageCount> distinctSources{};  // after preprocessing + pruning
    std::array<size_t, kStageCount> distinctModules{};  // after compiling, by SPIR-V bytes
};

struct CompiledPass {
    size_t shaderIndex = 0;  // into the shaders given to build()
    size_t passIndex = 0;    // into LoadedShader::passes
    std::vector<CompiledVariant> variants;  // enumeration order
    PassBuildStats stats;
    // Per declared keyword set (PassKeywords::sets order): the StageBits whose program changes
    // with that set's choice. A set with mask 0 does not affect the pass at all.
    std::vector<uint32_t> setStageEffects;
};

struct BuildOutput {
    std::vector<CompiledPass> passes;
    std::vector<CompiledProgram> programs;  // deduplicated by bytes, in first-use order
    size_t compiledSources = 0;             // glslang compilations
    size_t preprocessedPrograms = 0;        // glslang preprocessing runs (before pruning)
    size_t cachedSources = 0;               // of compiledSources, taken from the program cache
    size_t cachedStageSources = 0;          // pruned (variant, stage) sources taken from it
    // Sum over compiled sources of their in-process compile CPU time (glslang, optimiser,
    // validator, reflection), excluding preprocessing and dedup: divided by the thread count, the
    // floor a parallel build of these distinct programs cannot beat. Measured: not deterministic.
    double compileSeconds = 0;
};

// Runs the build. Diagnostics name the shader, pass, stage and keywords; an error shared by many
// variants is reported once, with the number of variants it affects. Returns nullopt when any
// program failed (nothing should be written then).
std::optional<BuildOutput> buildPrograms(const std::vector<LoadedShader>& shaders,
                                         const includes::SourceMap& sourceMap,
                                         const BuildOptions& options, DiagnosticSink& sink);

}  // namespace varc::compiler
