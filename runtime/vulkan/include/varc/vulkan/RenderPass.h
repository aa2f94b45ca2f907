// SPDX-License-Identifier: Apache-2.0
// RenderPass: the Vulkan calls that make a one-subpass render pass and a framebuffer for it, shared
// by RenderTarget and the deferred renderer's light and decode passes.
#pragma once

#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>

#include "varc/core/Result.h"
#include "varc/vulkan/UniqueHandle.h"

namespace varc::vulkan {

// Creates a render pass of the single subpass |subpass| over |attachments|, ordered against
// other work by |dependencies|. Errors: ErrorCode::VulkanError from vkCreateRenderPass.
Result<UniqueHandle<VkRenderPass>> createOneSubpassPass(
    VkDevice device, std::span<const VkAttachmentDescription> attachments,
    const VkSubpassDescription& subpass, std::span<const VkSubpassDependency> dependencies);

// Creates a one-layer |width| x |height| framebuffer of |pass| (or any pass compatible with it)
// over |views|, in attachment order. Errors: ErrorCode::VulkanError from vkCreateFramebuffer.
Result<UniqueHandle<VkFramebuffer>> createPassFramebuffer(VkDevice device, VkRenderPass pass,
                                                          std::span<const VkImageView> views,
                                                          uint32_t width, uint32_t height);

}  // namespace varc::vulkan
