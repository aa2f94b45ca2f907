// SPDX-License-Identifier: Apache-2.0
// Phase 2 of the compile driver: one distinct, pruned stage program to validated SPIR-V with its
// reflection (glslang -> SPIRV-Tools optimise -> validate -> reflect -> strip debug names), or
// taken from the program cache.
#pragma once

#include <cstdint>
#include <functional>
#include <string_view>
#include <vector>

#include "varc/core/Diagnostic.h"
#include "varc/driver/CompileDriver.h"
#include "varc/driver/ProgramCache.h"
#include "varc/includes/SourceMap.h"
#include "varc/pack/ProgramReflection.h"

namespace varc::driver::detail {

struct StageProgram {
    std::string_view text;  // preprocessed and pruned
    shaderlab::ProgramLanguage language = shaderlab::ProgramLanguage::Cg;
    Stage stage = Stage::Vertex;
    std::string_view entryPoint;
    SourceLocation origin;  // the program block, for errors without a line of their own
};

struct CompiledSource {
    bool ok = false;
    bool fromCache = false;
    double seconds = 0;  // CPU time of the compile on its worker thread
    std::vector<uint32_t> spirv;
    pack::ProgramReflection reflection;
    std::vector<Diagnostic> diagnostics;  // glslang's, mapped through |sourceMap|, and ours
};

// Compiles |program| as |options| say. With a |cache| (may be null) a hit skips the compile and
// a fresh compile is stored; a failed store goes to |onCacheFailure| and the build goes on.
// Thread-safe for distinct programs.
CompiledSource compileStageProgram(const StageProgram& program, const BuildOptions& options,
                                   const ProgramCache* cache, const includes::SourceMap& sourceMap,
                                   const std::function<void(const Status&)>& onCacheFailure);

// CPU time of the calling thread: unlike wall time, not inflated by other processes.
double threadCpuSeconds();
// CPU time of the whole process (every thread).
double processCpuSeconds();

}  // namespace varc::driver::detail
