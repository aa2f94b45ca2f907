// SPDX-License-Identifier: Apache-2.0
// RenderPass: one-subpass render passes and their framebuffers.
#include "varc/vulkan/RenderPass.h"

#include "varc/vulkan/CheckVk.h"

namespace varc::vulkan {

Result<UniqueHandle<VkRenderPass>> createOneSubpassPass(
    VkDevice device, std::span<const VkAttachmentDescription> attachments,
    const VkSubpassDescription& subpass, std::span<const VkSubpassDependency> dependencies) {
    VkRenderPassCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
    info.attachmentCount = static_cast<uint32_t>(attachments.size());
    info.pAttachments = attachments.data();
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = static_cast<uint32_t>(dependencies.size());
    info.pDependencies = dependencies.data();
    VkRenderPass pass = VK_NULL_HANDLE;
    if (Status status = checkVk(vkCreateRenderPass(device, &info, nullptr, &pass),
                                "vkCreateRenderPass", CallSite::current());
        !status) {
        return status.error();
    }
    return UniqueHandle<VkRenderPass>(device, pass);
}

Result<UniqueHandle<VkFramebuffer>> createPassFramebuffer(VkDevice device, VkRenderPass pass,
                                                          std::span<const VkImageView> views,
                                                          uint32_t width, uint32_t height) {
    VkFramebufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
    info.renderPass = pass;
    info.attachmentCount = static_cast<uint32_t>(views.size());
    info.pAttachments = views.data();
    info.width = width;
    info.height = height;
    info.layers = 1;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    if (Status status = checkVk(vkCreateFramebuffer(device, &info, nullptr, &framebuffer),
                                "vkCreateFramebuffer", CallSite::current());
        !status) {
        return status.error();
    }
    return UniqueHandle<VkFramebuffer>(device, framebuffer);
}

}  // namespace varc::vulkan
