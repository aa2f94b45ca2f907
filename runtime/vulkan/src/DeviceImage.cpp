// SPDX-License-Identifier: Apache-2.0
// DeviceImage: a VkImage with its memory and one view, plus layout-transition helpers.
#include "varc/vulkan/DeviceImage.h"

#include <utility>

#include "varc/vulkan/CheckVk.h"

namespace varc::vulkan {

namespace {

Result<UniqueHandle<VkImageView>> createView(const VulkanContext& context, VkImage image,
                                             const DeviceImageDesc& desc) {
    VkImageViewCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
    info.image = image;
    info.viewType = desc.cube     ? VK_IMAGE_VIEW_TYPE_CUBE
                    : desc.volume ? VK_IMAGE_VIEW_TYPE_3D
                                  : VK_IMAGE_VIEW_TYPE_2D;
    info.format = desc.format;
    info.subresourceRange = {desc.aspect, 0, desc.mipLevels, 0, desc.cube ? 6u : 1u};
    VkImageView view = VK_NULL_HANDLE;
    if (Status status = checkVk(vkCreateImageView(context.device(), &info, nullptr, &view),
                                "vkCreateImageView", CallSite::current());
        !status) {
        return status.error();
    }
    return UniqueHandle<VkImageView>(context.device(), view);
}

}  // namespace

Result<DeviceImage> createDeviceImage(const VulkanContext& context, const DeviceImageDesc& desc,
                                      const std::string& name) {
    VkImageCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
    info.flags = desc.cube ? VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT : 0;
    info.imageType = desc.volume ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D;
    info.format = desc.format;
    info.extent = {desc.width, desc.height, desc.volume ? desc.depth : 1};
    info.mipLevels = desc.mipLevels;
    info.arrayLayers = desc.cube ? 6 : 1;
    info.samples = VK_SAMPLE_COUNT_1_BIT;
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = desc.usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImage rawImage = VK_NULL_HANDLE;
    if (Status status = checkVk(vkCreateImage(context.device(), &info, nullptr, &rawImage),
                                "vkCreateImage", CallSite::current());
        !status) {
        return status.error();
    }
    DeviceImage result;
    result.image = UniqueHandle<VkImage>(context.device(), rawImage);
    context.nameObject(result.image, name);

    VkMemoryRequirements requirements{};
    vkGetImageMemoryRequirements(context.device(), rawImage, &requirements);
    Result<UniqueHandle<VkDeviceMemory>> memory =
        context.allocateMemory(requirements, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    if (!memory) return memory.error();
    result.memory = std::move(*memory);
    if (Status status =
            checkVk(vkBindImageMemory(context.device(), rawImage, result.memory.get(), 0),
                    "vkBindImageMemory", CallSite::current());
        !status) {
        return status.error();
    }
    Result<UniqueHandle<VkImageView>> view = createView(context, rawImage, desc);
    if (!view) return view.error();
    result.view = std::move(*view);
    context.nameObject(result.view, name + " view");
    return result;
}

void transitionLayout(VkCommandBuffer commands, VkImage image, VkImageAspectFlags aspect,
                      const LayoutTransition& transition) {
    VkImageMemoryBarrier barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
    barrier.srcAccessMask = transition.srcAccess;
    barrier.dstAccessMask = transition.dstAccess;
    barrier.oldLayout = transition.from;
    barrier.newLayout = transition.to;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = {aspect, transition.baseMipLevel, transition.mipLevelCount, 0,
                                VK_REMAINING_ARRAY_LAYERS};
    vkCmdPipelineBarrier(commands, transition.srcStages, transition.dstStages, 0, 0, nullptr, 0,
                         nullptr, 1, &barrier);
}

}  // namespace varc::vulkan
