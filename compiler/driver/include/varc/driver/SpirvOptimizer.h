// SPDX-License-Identifier: Apache-2.0
// SPIRV-Tools: legalise, optimise (-O0/-O/-Os) and validate SPIR-V modules for Vulkan 1.0.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace varc::driver {

enum class OptimizationLevel { None, Performance, Size };  // -O0, -O (default), -Os

// Parses "-O0", "-O", "-Os" (also "0", "performance", "size").
std::optional<OptimizationLevel> parseOptimizationLevel(std::string_view text);

struct SpirvResult {
    bool ok = false;
    std::vector<uint32_t> spirv;
    std::string message;  // SPIRV-Tools' messages on failure
};

// Runs HLSL legalisation (always: glslang's HLSL output needs it), then the passes of |level|,
// then strips reflection-only decorations (HLSL semantics) and compacts ids, so equal programs
// give equal bytes. Deterministic for equal input.
SpirvResult optimizeSpirv(const std::vector<uint32_t>& spirv, OptimizationLevel level);

// |spirv| without debug instructions (OpName, OpMemberName, OpSource, OpLine, ...): what ships
// when names are not asked for. The pack's reflection, taken before, keeps every name it needs.
SpirvResult stripDebugInfo(const std::vector<uint32_t>& spirv);

// Validates |spirv| for Vulkan 1.0; returns the validator's message, or nullopt when valid.
std::optional<std::string> validateSpirv(const std::vector<uint32_t>& spirv);

// Validates glslang's output as the optimiser receives it (before HLSL legalisation, with the
// relaxed block layout); returns the validator's message, or nullopt when valid.
std::optional<std::string> validateBeforeLegalization(const std::vector<uint32_t>& spirv);

// What validateAndOptimize made of one module: either the input was refused, or it was
// optimised (which may still fail, as optimized.ok and optimized.message say).
struct OptimizeOutcome {
    std::optional<std::string> invalidInput;  // the validator's message on glslang's output
    SpirvResult optimized;                    // set when the input was valid
};

// validateBeforeLegalization, then, for a valid module, optimizeSpirv: the unit of work an
// optimiser worker process runs (OptimizerWorker.h), also run in-process.
OptimizeOutcome validateAndOptimize(const std::vector<uint32_t>& spirv, OptimizationLevel level);

// "v2023.1" for pack headers.
std::string spirvToolsVersionString();

}  // namespace varc::driver
