// SPDX-License-Identifier: Apache-2.0
// SPIRV-Tools: legalise, optimise (-O0/-O/-Os) and validate SPIR-V modules for Vulkan 1.0.
#include "varc/driver/SpirvOptimizer.h"

#include <spirv-tools/libspirv.hpp>
#include <spirv-tools/optimizer.hpp>

namespace varc::driver {

namespace {

constexpr spv_target_env kTargetEnv = SPV_ENV_VULKAN_1_0;

// Collects SPIRV-Tools messages into one string.
spvtools::MessageConsumer collectInto(std::string& sink) {
    return [&sink](spv_message_level_t, const char*, const spv_position_t& position,
                   const char* message) {
        if (!sink.empty()) sink += "\n";
        sink += "word " + std::to_string(position.index) + ": " + message;
    };
}

}  // namespace

std::optional<OptimizationLevel> parseOptimizationLevel(std::string_view text) {
    if (text == "-O0" || text == "0") return OptimizationLevel::None;
    if (text == "-O" || text == "performance") return OptimizationLevel::Performance;
    if (text == "-Os" || text == "size") return OptimizationLevel::Size;
    return std::nullopt;
}

SpirvResult optimizeSpirv(const std::vector<uint32_t>& spirv, OptimizationLevel level) {
    SpirvResult result;
    spvtools::Optimizer optimizer(kTargetEnv);
    optimizer.SetMessageConsumer(collectInto(result.message));
    optimizer.RegisterLegalizationPasses();
    if (level == OptimizationLevel::Performance) optimizer.RegisterPerformancePasses();
    if (level == OptimizationLevel::Size) optimizer.RegisterSizePasses();
    optimizer.RegisterPass(spvtools::CreateStripReflectInfoPass());
    // Renumber ids densely: glslang numbers ids over all code it parsed, so two programs that
    // differ only in stripped code would otherwise differ in bytes and escape deduplication.
    optimizer.RegisterPass(spvtools::CreateCompactIdsPass());
    spvtools::ValidatorOptions validatorOptions;
    spvtools::OptimizerOptions options;
    options.set_run_validator(false);  // validated once, explicitly, afterwards
    options.set_validator_options(validatorOptions);
    result.ok = optimizer.Run(spirv.data(), spirv.size(), &result.spirv, options);
    return result;
}

SpirvResult stripDebugInfo(const std::vector<uint32_t>& spirv) {
    SpirvResult result;
    spvtools::Optimizer optimizer(kTargetEnv);
    optimizer.SetMessageConsumer(collectInto(result.message));
    optimizer.RegisterPass(spvtools::CreateStripDebugInfoPass());
    spvtools::OptimizerOptions options;
    options.set_run_validator(false);
    result.ok = optimizer.Run(spirv.data(), spirv.size(), &result.spirv, options);
    return result;
}

// Uniform and storage blocks may use the relaxed block layout (VK_KHR_relaxed_block_layout, core
// in Vulkan 1.1): HLSL's cbuffer packing puts a float3 right after a float (offset 4), which
// glslang keeps for `cbuffer` blocks and which every HLSL shader of Unity's era relies on. The
// runtime enables the extension (docs/SHADER_ABI.md §1).
std::optional<std::string> validateSpirv(const std::vector<uint32_t>& spirv) {
    spvtools::SpirvTools tools(kTargetEnv);
    std::string message;
    tools.SetMessageConsumer(collectInto(message));
    spvtools::ValidatorOptions options;
    options.SetRelaxBlockLayout(true);
    if (tools.Validate(spirv.data(), spirv.size(), options)) return std::nullopt;
    return message.empty() ? std::string("invalid SPIR-V") : message;
}

// glslang's HLSL output is not valid Vulkan SPIR-V until legalised (opaque values in
// structs and function parameters, pointers to them, relaxed block layout): the validator's
// before-legalisation mode accepts exactly that and still refuses malformed modules, which would
// otherwise reach the optimiser (one such module crashed it: issue #27). The block layout check
// is skipped here: it was most of this validation's cost (Unity's cbuffers are large), and
// validateSpirv checks the layout of the module that ships.
std::optional<std::string> validateBeforeLegalization(const std::vector<uint32_t>& spirv) {
    spvtools::SpirvTools tools(kTargetEnv);
    std::string message;
    tools.SetMessageConsumer(collectInto(message));
    spvtools::ValidatorOptions options;
    options.SetBeforeHlslLegalization(true);
    options.SetRelaxBlockLayout(true);
    options.SetSkipBlockLayout(true);
    if (tools.Validate(spirv.data(), spirv.size(), options)) return std::nullopt;
    return message.empty() ? std::string("invalid SPIR-V") : message;
}

OptimizeOutcome validateAndOptimize(const std::vector<uint32_t>& spirv, OptimizationLevel level) {
    OptimizeOutcome outcome;
    outcome.invalidInput = validateBeforeLegalization(spirv);
    if (!outcome.invalidInput) outcome.optimized = optimizeSpirv(spirv, level);
    return outcome;
}

std::string spirvToolsVersionString() { return spvSoftwareVersionString(); }

}  // namespace varc::driver
