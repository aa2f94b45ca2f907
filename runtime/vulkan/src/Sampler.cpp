// SPDX-License-Identifier: Apache-2.0
// Samplers: a small description and a factory.
#include "varc/vulkan/Sampler.h"

#include <algorithm>

#include "varc/vulkan/CheckVk.h"

namespace varc::vulkan {

Result<UniqueHandle<VkSampler>> createSampler(const VulkanContext& context,
                                              const SamplerDesc& desc) {
    bool anisotropy = desc.maxAnisotropy > 1.0f && context.enabledFeatures().samplerAnisotropy;
    VkSamplerCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
    info.magFilter = desc.filter;
    info.minFilter = desc.filter;
    info.mipmapMode = desc.mipmapMode;
    info.addressModeU = desc.addressMode;
    info.addressModeV = desc.addressMode;
    info.addressModeW = desc.addressMode;
    info.anisotropyEnable = anisotropy ? VK_TRUE : VK_FALSE;
    info.maxAnisotropy =
        anisotropy ? std::min(desc.maxAnisotropy, context.properties().limits.maxSamplerAnisotropy)
                   : 1.0f;
    info.minLod = 0.0f;
    info.maxLod = desc.maxLod;
    info.borderColor = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
    VkSampler sampler = VK_NULL_HANDLE;
    if (Status status = checkVk(vkCreateSampler(context.device(), &info, nullptr, &sampler),
                                "vkCreateSampler", CallSite::current());
        !status) {
        return status.error();
    }
    UniqueHandle<VkSampler> handle(context.device(), sampler);
    context.nameObject(handle, desc.name);
    return handle;
}

}  // namespace varc::vulkan
