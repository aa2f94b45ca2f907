// SPDX-License-Identifier: Apache-2.0
// Samplers: a small description and a factory.
#pragma once

#include <vulkan/vulkan.h>

#include <string>

#include "varc/core/Result.h"
#include "varc/vulkan/UniqueHandle.h"
#include "varc/vulkan/VulkanContext.h"

namespace varc::vulkan {

struct SamplerDesc {
    VkFilter filter = VK_FILTER_LINEAR;  // both magnification and minification
    VkSamplerMipmapMode mipmapMode = VK_SAMPLER_MIPMAP_MODE_LINEAR;
    VkSamplerAddressMode addressMode = VK_SAMPLER_ADDRESS_MODE_REPEAT;  // u, v and w
    float maxLod = VK_LOD_CLAMP_NONE;
    // > 1 enables anisotropic filtering, clamped to the device limit; ignored when the device
    // lacks samplerAnisotropy.
    float maxAnisotropy = 1.0f;
    std::string name = "sampler";
};

// Errors: ErrorCode::VulkanError.
Result<UniqueHandle<VkSampler>> createSampler(const VulkanContext& context,
                                              const SamplerDesc& desc = {});

}  // namespace varc::vulkan
