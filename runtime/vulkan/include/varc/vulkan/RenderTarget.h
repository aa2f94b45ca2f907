// SPDX-License-Identifier: Apache-2.0
// RenderTarget: an offscreen colour (+ depth/stencil) image, its render passes and framebuffer.
#pragma once

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "varc/core/Result.h"
#include "varc/image/Image.h"
#include "varc/vulkan/DeviceImage.h"
#include "varc/vulkan/UniqueHandle.h"
#include "varc/vulkan/VulkanContext.h"

namespace varc::vulkan {

enum class ColorFormat {
    Rgba8Unorm,   // VK_FORMAT_R8G8B8A8_UNORM (LDR)
    Rgba8Srgb,    // VK_FORMAT_R8G8B8A8_SRGB: shaders write linear, memory holds sRGB-encoded
    Rgba16Float,  // VK_FORMAT_R16G16B16A16_SFLOAT (HDR)
    Rgba32Float,  // VK_FORMAT_R32G32B32A32_SFLOAT (HDR, exact float readback)
};

VkFormat toVkFormat(ColorFormat format);
bool isFloat(ColorFormat format);
const char* toString(ColorFormat format);  // "Rgba8Unorm", ...

enum class LoadOp {
    Clear,  // start from the target's clear colour, depth and stencil
    Load,   // keep what earlier passes rendered
};

struct RenderTargetDesc {
    uint32_t width = 256;
    uint32_t height = 256;
    ColorFormat color = ColorFormat::Rgba8Unorm;
    // Further colour attachments 1..N (multiple render targets, e.g. a G-buffer); cleared to 0.
    std::vector<ColorFormat> extraColors;
    // Clear colours of the extra attachments, in order; attachments beyond this list clear to 0.
    std::vector<std::array<float, 4>> extraClearColors;
    // Adds a VK_FORMAT_D32_SFLOAT_S8_UINT attachment, or D24_UNORM_S8_UINT where D32S8 is not
    // supported.
    bool depthStencil = true;
    // Makes the depth aspect samplable (e.g. a deferred renderer's _CameraDepthTexture): the depth
    // image gets VK_IMAGE_USAGE_SAMPLED_BIT and a depth-only view, depthSampleView().
    bool sampledDepth = false;
    // Lets the depth image be copied from (VK_IMAGE_USAGE_TRANSFER_SRC_BIT), e.g. into a layer
    // of a cube map.
    bool copyableDepth = false;
    std::array<float, 4> clearColor{0.0f, 0.0f, 0.0f, 1.0f};
    float clearDepth = 1.0f;
    uint32_t clearStencil = 0;
    std::string name = "RenderTarget";  // debug name prefix
};

// Between submissions the colour image is in COLOR_ATTACHMENT_OPTIMAL and the depth image in
// DEPTH_STENCIL_ATTACHMENT_OPTIMAL; create() clears both once, so LoadOp::Load is valid from
// the start. The two render passes differ only in load ops, so they are compatible: a pipeline
// made with renderPass(LoadOp::Clear) works in either.
class RenderTarget {
public:
    // Creates the images, both render passes and the framebuffer, and clears the target.
    // Errors: ErrorCode::Unsupported when the size exceeds the framebuffer limits, the colour
    // format cannot be a colour attachment or no D32S8/D24S8 format is supported;
    // ErrorCode::VulkanError otherwise. A zero width or height is a programmer error.
    static Result<RenderTarget> create(VulkanContext& context, const RenderTargetDesc& desc);

    uint32_t width() const { return mDesc.width; }
    uint32_t height() const { return mDesc.height; }
    const RenderTargetDesc& desc() const { return mDesc; }
    VkFormat colorFormat() const { return toVkFormat(mDesc.color); }
    uint32_t colorAttachmentCount() const { return 1 + static_cast<uint32_t>(mDesc.extraColors.size()); }
    // VK_FORMAT_UNDEFINED without a depth/stencil attachment.
    VkFormat depthStencilFormat() const { return mDepthFormat; }
    VkRenderPass renderPass(LoadOp op = LoadOp::Clear) const;
    VkFramebuffer framebuffer() const { return mFramebuffer.get(); }
    VkImage colorImage() const { return mColor.image.get(); }
    VkImageView colorView() const { return mColor.view.get(); }
    // Colour attachment |attachment| (0 = colorImage()); a programmer error when out of range.
    VkImage colorImage(uint32_t attachment) const;
    VkImageView colorView(uint32_t attachment) const;
    ColorFormat attachmentFormat(uint32_t attachment) const;
    // The depth/stencil image and its view of both aspects (VK_NULL_HANDLE without one), and the
    // depth-only view of a sampledDepth target (VK_NULL_HANDLE otherwise).
    VkImage depthImage() const { return mDepth.image.get(); }
    VkImageView depthView() const { return mDepth.view.get(); }
    VkImageView depthSampleView() const { return mDepthSampleView.get(); }
    VkViewport viewport() const;  // the whole target, depth 0..1
    VkRect2D area() const;        // the whole target

    // Records vkCmdBeginRenderPass over the whole target with |op| and inline contents.
    void begin(VkCommandBuffer commands, LoadOp op = LoadOp::Clear) const;
    void end(VkCommandBuffer commands) const;

    // Copies the colour image to a host-visible buffer and waits. 8-bit formats give Rgba8
    // images of the stored bytes (still sRGB-encoded for Rgba8Srgb); float formats give
    // RgbaFloat images (half floats converted exactly). Errors: ErrorCode::VulkanError.
    Result<image::Image> readback(VulkanContext& context, uint32_t attachment = 0) const;

private:
    Status createImages(const VulkanContext& context);
    Status createRenderPasses(const VulkanContext& context);
    Status createFramebuffer(const VulkanContext& context);
    Status clearOnce(VulkanContext& context) const;
    void recordReadback(VkCommandBuffer commands, VkBuffer destination, uint32_t attachment) const;
    Status createDepthSampleView(const VulkanContext& context);

    RenderTargetDesc mDesc;
    VkFormat mDepthFormat = VK_FORMAT_UNDEFINED;
    DeviceImage mColor;
    std::vector<DeviceImage> mExtraColors;
    DeviceImage mDepth;
    UniqueHandle<VkImageView> mDepthSampleView;
    UniqueHandle<VkRenderPass> mClearPass;
    UniqueHandle<VkRenderPass> mLoadPass;
    UniqueHandle<VkFramebuffer> mFramebuffer;
};

}  // namespace varc::vulkan
