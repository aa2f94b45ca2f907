// SPDX-License-Identifier: Apache-2.0
// Shader modules from SPIR-V words or .spv files.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "varc/core/Result.h"
#include "varc/vulkan/UniqueHandle.h"
#include "varc/vulkan/VulkanContext.h"

namespace varc::vulkan {

// SPIR-V's first word.
constexpr uint32_t kSpirvMagic = 0x07230203;

// Reads a .spv file (host-endian words, as glslangValidator -V writes them).
// Errors: ErrorCode::IoError when unreadable; ErrorCode::InvalidInput when the size is not a
// positive multiple of 4 or the magic number is wrong.
Result<std::vector<uint32_t>> readSpirvFile(const std::string& path);

// Creates a shader module from |spirv| and names it |name|.
// Errors: ErrorCode::InvalidInput without the SPIR-V magic; ErrorCode::VulkanError.
Result<UniqueHandle<VkShaderModule>> createShaderModule(const VulkanContext& context,
                                                        std::span<const uint32_t> spirv,
                                                        const std::string& name = "shader");

// readSpirvFile + createShaderModule, named after |path|.
Result<UniqueHandle<VkShaderModule>> loadShaderModule(const VulkanContext& context,
                                                      const std::string& path);

}  // namespace varc::vulkan
