// SPDX-License-Identifier: Apache-2.0
// Shader modules from SPIR-V words or .spv files.
#include "varc/vulkan/ShaderModule.h"

#include <cstring>

#include "varc/core/FileRead.h"
#include "varc/vulkan/CheckVk.h"

namespace varc::vulkan {

Result<std::vector<uint32_t>> readSpirvFile(const std::string& path) {
    Result<std::string> read = readFile(path);
    if (!read) return read.error();
    const std::string& bytes = *read;
    if (bytes.empty() || bytes.size() % 4 != 0) {
        return makeError(ErrorCode::InvalidInput,
                         "'" + path + "' is not SPIR-V: " + std::to_string(bytes.size()) +
                             " bytes is not a positive multiple of 4");
    }
    std::vector<uint32_t> words(bytes.size() / 4);
    std::memcpy(words.data(), bytes.data(), bytes.size());
    if (words[0] != kSpirvMagic) {
        return makeError(ErrorCode::InvalidInput, "'" + path + "' lacks the SPIR-V magic number");
    }
    return words;
}

Result<UniqueHandle<VkShaderModule>> createShaderModule(const VulkanContext& context,
                                                        std::span<const uint32_t> spirv,
                                                        const std::string& name) {
    if (spirv.empty() || spirv[0] != kSpirvMagic) {
        return makeError(ErrorCode::InvalidInput, "shader '" + name + "' is not SPIR-V");
    }
    VkShaderModuleCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    info.codeSize = spirv.size_bytes();
    info.pCode = spirv.data();
    VkShaderModule module = VK_NULL_HANDLE;
    if (Status status = checkVk(vkCreateShaderModule(context.device(), &info, nullptr, &module),
                                "vkCreateShaderModule", CallSite::current());
        !status) {
        return status.error();
    }
    UniqueHandle<VkShaderModule> handle(context.device(), module);
    context.nameObject(handle, name);
    return handle;
}

Result<UniqueHandle<VkShaderModule>> loadShaderModule(const VulkanContext& context,
                                                      const std::string& path) {
    Result<std::vector<uint32_t>> words = readSpirvFile(path);
    if (!words) return words.error();
    return createShaderModule(context, *words, path);
}

}  // namespace varc::vulkan
