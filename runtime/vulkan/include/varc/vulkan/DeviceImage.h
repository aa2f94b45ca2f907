// SPDX-License-Identifier: Apache-2.0
// DeviceImage: a VkImage with its memory and one view, plus layout-transition helpers.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>

#include "varc/core/Result.h"
#include "varc/vulkan/UniqueHandle.h"
#include "varc/vulkan/VulkanContext.h"

namespace varc::vulkan {

struct DeviceImageDesc {
    VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
    uint32_t width = 1;
    uint32_t height = 1;
    uint32_t mipLevels = 1;
    bool cube = false;    // six array layers, a cube view
    uint32_t depth = 1;   // slices of a volume
    bool volume = false;  // a 3D image and view of |depth| slices (not with |cube|)
    VkImageUsageFlags usage = 0;
    VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;
};

// Memory first, so the view and image are destroyed before it is freed.
struct DeviceImage {
    UniqueHandle<VkDeviceMemory> memory;
    UniqueHandle<VkImage> image;
    UniqueHandle<VkImageView> view;
};

// Creates an optimal-tiling, device-local image in VK_IMAGE_LAYOUT_UNDEFINED and a view of all
// its levels and layers; names both after |name|.
Result<DeviceImage> createDeviceImage(const VulkanContext& context, const DeviceImageDesc& desc,
                                      const std::string& name);

// One image layout transition with its memory dependency.
struct LayoutTransition {
    VkImageLayout from = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImageLayout to = VK_IMAGE_LAYOUT_UNDEFINED;
    VkPipelineStageFlags srcStages = VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT;
    VkAccessFlags srcAccess = 0;
    VkPipelineStageFlags dstStages = VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT;
    VkAccessFlags dstAccess = 0;
    uint32_t baseMipLevel = 0;
    uint32_t mipLevelCount = VK_REMAINING_MIP_LEVELS;
};

// Records a vkCmdPipelineBarrier for |transition| over every layer of |image|.
void transitionLayout(VkCommandBuffer commands, VkImage image, VkImageAspectFlags aspect,
                      const LayoutTransition& transition);

}  // namespace varc::vulkan
