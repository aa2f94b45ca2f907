// SPDX-License-Identifier: Apache-2.0
// RenderTarget: an offscreen colour (+ depth/stencil) image, its render passes and framebuffer.
#include "varc/vulkan/RenderTarget.h"

#include <cstring>
#include <utility>
#include <vector>

#include "varc/core/Check.h"
#include "varc/vulkan/Buffer.h"
#include "varc/vulkan/CheckVk.h"
#include "varc/vulkan/RenderPass.h"

namespace varc::vulkan {

namespace {

bool supportsOptimal(VkPhysicalDevice device, VkFormat format, VkFormatFeatureFlags features) {
    VkFormatProperties properties{};
    vkGetPhysicalDeviceFormatProperties(device, format, &properties);
    return (properties.optimalTilingFeatures & features) == features;
}

VkFormat pickDepthStencilFormat(VkPhysicalDevice device) {
    for (VkFormat format : {VK_FORMAT_D32_SFLOAT_S8_UINT, VK_FORMAT_D24_UNORM_S8_UINT}) {
        if (supportsOptimal(device, format, VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT)) {
            return format;
        }
    }
    return VK_FORMAT_UNDEFINED;
}

uint32_t bytesPerPixel(ColorFormat format) {
    switch (format) {
        case ColorFormat::Rgba8Unorm:
        case ColorFormat::Rgba8Srgb:
            return 4;
        case ColorFormat::Rgba16Float:
            return 8;
        case ColorFormat::Rgba32Float:
            return 16;
    }
    return 4;
}

// Orders this pass after earlier passes and copies on the target, and later transfers and
// shader reads after this pass.
std::array<VkSubpassDependency, 2> passDependencies() {
    constexpr VkPipelineStageFlags kAttachmentStages =
        VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT | VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
        VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    constexpr VkAccessFlags kAttachmentWrites =
        VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    constexpr VkAccessFlags kAttachmentAccess = kAttachmentWrites |
                                                VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
                                                VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
    VkSubpassDependency before{};
    before.srcSubpass = VK_SUBPASS_EXTERNAL;
    before.dstSubpass = 0;
    before.srcStageMask = kAttachmentStages | VK_PIPELINE_STAGE_TRANSFER_BIT;
    before.srcAccessMask = kAttachmentWrites;
    before.dstStageMask = kAttachmentStages;
    before.dstAccessMask = kAttachmentAccess;
    VkSubpassDependency after{};
    after.srcSubpass = 0;
    after.dstSubpass = VK_SUBPASS_EXTERNAL;
    after.srcStageMask = kAttachmentStages;
    after.srcAccessMask = kAttachmentWrites;
    after.dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
    after.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_SHADER_READ_BIT;
    return {before, after};
}

// A Clear pass starts from UNDEFINED (contents are discarded anyway); a Load pass expects the
// layout every pass ends in, |steadyLayout|. Stencil ops follow |stencil|.
VkAttachmentDescription attachment(VkFormat format, LoadOp op, VkImageLayout steadyLayout,
                                   bool stencil) {
    bool clear = op == LoadOp::Clear;
    VkAttachmentLoadOp load = clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
    VkAttachmentDescription description{};
    description.format = format;
    description.samples = VK_SAMPLE_COUNT_1_BIT;
    description.loadOp = load;
    description.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    description.stencilLoadOp = stencil ? load : VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    description.stencilStoreOp =
        stencil ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
    description.initialLayout = clear ? VK_IMAGE_LAYOUT_UNDEFINED : steadyLayout;
    description.finalLayout = steadyLayout;
    return description;
}

Result<UniqueHandle<VkRenderPass>> createRenderPass(VkDevice device,
                                                    const std::vector<VkFormat>& colors,
                                                    VkFormat depthStencil, LoadOp op) {
    std::vector<VkAttachmentDescription> attachments;
    std::vector<VkAttachmentReference> colorRefs;
    for (VkFormat color : colors) {
        colorRefs.push_back(
            {static_cast<uint32_t>(attachments.size()), VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL});
        attachments.push_back(
            attachment(color, op, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, false));
    }
    VkAttachmentReference depthRef{static_cast<uint32_t>(attachments.size()),
                                   VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    if (depthStencil != VK_FORMAT_UNDEFINED) {
        attachments.push_back(
            attachment(depthStencil, op, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL, true));
    }
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = static_cast<uint32_t>(colorRefs.size());
    subpass.pColorAttachments = colorRefs.data();
    subpass.pDepthStencilAttachment = depthStencil != VK_FORMAT_UNDEFINED ? &depthRef : nullptr;
    return createOneSubpassPass(device, attachments, subpass, passDependencies());
}

// Converts |bytes| read back from a |format| image to an Image.
image::Image convertReadback(const std::byte* bytes, uint32_t width, uint32_t height,
                             ColorFormat format) {
    if (!isFloat(format)) {
        image::Image image(width, height, image::PixelFormat::Rgba8);
        std::memcpy(image.bytes().data(), bytes, image.bytes().size());
        return image;
    }
    image::Image image(width, height, image::PixelFormat::RgbaFloat);
    std::span<float> out = image.floats();
    if (format == ColorFormat::Rgba32Float) {
        std::memcpy(out.data(), bytes, out.size_bytes());
    } else {
        for (std::size_t i = 0; i < out.size(); ++i) {
            uint16_t half = 0;
            std::memcpy(&half, bytes + i * 2, 2);
            out[i] = image::halfToFloat(half);
        }
    }
    return image;
}

}  // namespace

VkFormat toVkFormat(ColorFormat format) {
    switch (format) {
        case ColorFormat::Rgba8Unorm:
            return VK_FORMAT_R8G8B8A8_UNORM;
        case ColorFormat::Rgba8Srgb:
            return VK_FORMAT_R8G8B8A8_SRGB;
        case ColorFormat::Rgba16Float:
            return VK_FORMAT_R16G16B16A16_SFLOAT;
        case ColorFormat::Rgba32Float:
            return VK_FORMAT_R32G32B32A32_SFLOAT;
    }
    return VK_FORMAT_UNDEFINED;
}

const char* toString(ColorFormat format) {
    switch (format) {
        case ColorFormat::Rgba8Unorm:
            return "Rgba8Unorm";
        case ColorFormat::Rgba8Srgb:
            return "Rgba8Srgb";
        case ColorFormat::Rgba16Float:
            return "Rgba16Float";
        case ColorFormat::Rgba32Float:
            return "Rgba32Float";
    }
    return "ColorFormat(unknown)";
}

bool isFloat(ColorFormat format) {
    return format == ColorFormat::Rgba16Float || format == ColorFormat::Rgba32Float;
}

Result<RenderTarget> RenderTarget::create(VulkanContext& context, const RenderTargetDesc& desc) {
    VARC_CHECK(desc.width > 0 && desc.height > 0) << "RenderTarget of zero size";
    RenderTarget target;
    target.mDesc = desc;
    if (Status status = target.createImages(context); !status) return status.error();
    if (Status status = target.createRenderPasses(context); !status) return status.error();
    if (Status status = target.createFramebuffer(context); !status) return status.error();
    if (Status status = target.clearOnce(context); !status) return status.error();
    return target;
}

Status RenderTarget::createImages(const VulkanContext& context) {
    const VkPhysicalDeviceLimits& limits = context.properties().limits;
    if (mDesc.width > limits.maxFramebufferWidth || mDesc.height > limits.maxFramebufferHeight) {
        return makeError(ErrorCode::Unsupported,
                         "render target " + std::to_string(mDesc.width) + "x" +
                             std::to_string(mDesc.height) + " exceeds the device's " +
                             std::to_string(limits.maxFramebufferWidth) + "x" +
                             std::to_string(limits.maxFramebufferHeight) + " limit");
    }
    DeviceImageDesc colorDesc;
    colorDesc.width = mDesc.width;
    colorDesc.height = mDesc.height;
    colorDesc.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                      VK_IMAGE_USAGE_SAMPLED_BIT;
    for (uint32_t i = 0; i < colorAttachmentCount(); ++i) {
        ColorFormat format = attachmentFormat(i);
        colorDesc.format = toVkFormat(format);
        if (!supportsOptimal(context.physicalDevice(), colorDesc.format,
                             VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT)) {
            return makeError(ErrorCode::Unsupported,
                             std::string("colour format ") + toString(format) +
                                 " cannot be a colour attachment on " + context.deviceName());
        }
        Result<DeviceImage> colorImage =
            createDeviceImage(context, colorDesc, mDesc.name + " colour " + std::to_string(i));
        if (!colorImage) return colorImage.error();
        if (i == 0) {
            mColor = std::move(*colorImage);
        } else {
            mExtraColors.push_back(std::move(*colorImage));
        }
    }
    if (!mDesc.depthStencil) return Ok{};

    mDepthFormat = pickDepthStencilFormat(context.physicalDevice());
    if (mDepthFormat == VK_FORMAT_UNDEFINED) {
        return makeError(ErrorCode::Unsupported,
                         "neither D32_SFLOAT_S8_UINT nor D24_UNORM_S8_UINT is supported");
    }
    DeviceImageDesc depthDesc = colorDesc;
    depthDesc.format = mDepthFormat;
    depthDesc.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    if (mDesc.copyableDepth) depthDesc.usage |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    if (mDesc.sampledDepth) {
        if (!supportsOptimal(context.physicalDevice(), mDepthFormat,
                             VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT)) {
            return makeError(
                ErrorCode::Unsupported,
                "the depth/stencil format cannot be sampled on " + context.deviceName());
        }
        depthDesc.usage |= VK_IMAGE_USAGE_SAMPLED_BIT;
    }
    depthDesc.aspect = VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
    Result<DeviceImage> depthImage =
        createDeviceImage(context, depthDesc, mDesc.name + " depth/stencil");
    if (!depthImage) return depthImage.error();
    mDepth = std::move(*depthImage);
    return mDesc.sampledDepth ? createDepthSampleView(context) : Status(Ok{});
}

// A view may name only one aspect of a depth/stencil image when it is sampled.
Status RenderTarget::createDepthSampleView(const VulkanContext& context) {
    VkImageViewCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
    info.image = mDepth.image.get();
    info.viewType = VK_IMAGE_VIEW_TYPE_2D;
    info.format = mDepthFormat;
    info.subresourceRange = {VK_IMAGE_ASPECT_DEPTH_BIT, 0, 1, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    if (Status status = checkVk(vkCreateImageView(context.device(), &info, nullptr, &view),
                                "vkCreateImageView", CallSite::current());
        !status) {
        return status;
    }
    mDepthSampleView = UniqueHandle<VkImageView>(context.device(), view);
    context.nameObject(mDepthSampleView, mDesc.name + " depth sample view");
    return Ok{};
}

VkImage RenderTarget::colorImage(uint32_t attachment) const {
    VARC_CHECK(attachment < colorAttachmentCount()) << "no colour attachment " << attachment;
    return attachment == 0 ? mColor.image.get() : mExtraColors[attachment - 1].image.get();
}

VkImageView RenderTarget::colorView(uint32_t attachment) const {
    VARC_CHECK(attachment < colorAttachmentCount()) << "no colour attachment " << attachment;
    return attachment == 0 ? mColor.view.get() : mExtraColors[attachment - 1].view.get();
}

ColorFormat RenderTarget::attachmentFormat(uint32_t attachment) const {
    return attachment == 0 ? mDesc.color : mDesc.extraColors.at(attachment - 1);
}

Status RenderTarget::createRenderPasses(const VulkanContext& context) {
    std::vector<VkFormat> colors;
    for (uint32_t i = 0; i < colorAttachmentCount(); ++i)
        colors.push_back(toVkFormat(attachmentFormat(i)));
    Result<UniqueHandle<VkRenderPass>> clearPass =
        createRenderPass(context.device(), colors, mDepthFormat, LoadOp::Clear);
    if (!clearPass) return clearPass.error();
    mClearPass = std::move(*clearPass);
    context.nameObject(mClearPass, mDesc.name + " clear pass");
    Result<UniqueHandle<VkRenderPass>> loadPass =
        createRenderPass(context.device(), colors, mDepthFormat, LoadOp::Load);
    if (!loadPass) return loadPass.error();
    mLoadPass = std::move(*loadPass);
    context.nameObject(mLoadPass, mDesc.name + " load pass");
    return Ok{};
}

Status RenderTarget::createFramebuffer(const VulkanContext& context) {
    std::vector<VkImageView> views{mColor.view.get()};
    for (const DeviceImage& extra : mExtraColors) views.push_back(extra.view.get());
    if (mDepth.view) views.push_back(mDepth.view.get());
    Result<UniqueHandle<VkFramebuffer>> framebuffer =
        createPassFramebuffer(context.device(), mClearPass.get(), views, mDesc.width, mDesc.height);
    if (!framebuffer) return framebuffer.error();
    mFramebuffer = std::move(*framebuffer);
    context.nameObject(mFramebuffer, mDesc.name + " framebuffer");
    return Ok{};
}

Status RenderTarget::clearOnce(VulkanContext& context) const {
    return context.submitAndWait([&](VkCommandBuffer commands) {
        begin(commands, LoadOp::Clear);
        end(commands);
    });
}

VkRenderPass RenderTarget::renderPass(LoadOp op) const {
    return op == LoadOp::Clear ? mClearPass.get() : mLoadPass.get();
}

VkViewport RenderTarget::viewport() const {
    return VkViewport{0.0f, 0.0f, static_cast<float>(mDesc.width), static_cast<float>(mDesc.height),
                      0.0f, 1.0f};
}

VkRect2D RenderTarget::area() const { return VkRect2D{{0, 0}, {mDesc.width, mDesc.height}}; }

void RenderTarget::begin(VkCommandBuffer commands, LoadOp op) const {
    std::vector<VkClearValue> clears(colorAttachmentCount() + 1);  // extra colours clear to 0
    const std::array<float, 4>& c = mDesc.clearColor;
    clears[0].color = {{c[0], c[1], c[2], c[3]}};
    for (size_t i = 0; i < mDesc.extraClearColors.size() && i + 1 < colorAttachmentCount(); ++i) {
        const std::array<float, 4>& e = mDesc.extraClearColors[i];
        clears[i + 1].color = {{e[0], e[1], e[2], e[3]}};
    }
    clears.back().depthStencil = {mDesc.clearDepth, mDesc.clearStencil};
    VkRenderPassBeginInfo info{};
    info.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
    info.renderPass = renderPass(op);
    info.framebuffer = mFramebuffer.get();
    info.renderArea = area();
    uint32_t clearCount = colorAttachmentCount() + (mDepth.view ? 1u : 0u);
    info.clearValueCount = op == LoadOp::Clear ? clearCount : 0u;
    info.pClearValues = clears.data();
    vkCmdBeginRenderPass(commands, &info, VK_SUBPASS_CONTENTS_INLINE);
}

void RenderTarget::end(VkCommandBuffer commands) const { vkCmdEndRenderPass(commands); }

Result<image::Image> RenderTarget::readback(VulkanContext& context, uint32_t attachment) const {
    VARC_CHECK(attachment < colorAttachmentCount()) << "no colour attachment " << attachment;
    ColorFormat format = attachmentFormat(attachment);
    VkDeviceSize size = VkDeviceSize{mDesc.width} * mDesc.height * bytesPerPixel(format);
    Result<Buffer> buffer = Buffer::create(context, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                           MemoryLocation::HostVisible, mDesc.name + " readback");
    if (!buffer) return buffer.error();
    Status copied = context.submitAndWait(
        [&](VkCommandBuffer commands) { recordReadback(commands, buffer->handle(), attachment); });
    if (!copied) return copied.error();
    return convertReadback(buffer->mapped(), mDesc.width, mDesc.height, format);
}

void RenderTarget::recordReadback(VkCommandBuffer commands, VkBuffer destination,
                                  uint32_t attachment) const {
    VkImage image = attachment == 0 ? mColor.image.get() : mExtraColors[attachment - 1].image.get();
    transitionLayout(
        commands, image, VK_IMAGE_ASPECT_COLOR_BIT,
        {VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
         VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
         VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT});
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {mDesc.width, mDesc.height, 1};
    vkCmdCopyImageToBuffer(commands, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, destination, 1,
                           &region);
    transitionLayout(
        commands, image, VK_IMAGE_ASPECT_COLOR_BIT,
        {VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
         VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
         VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT});
    VkBufferMemoryBarrier toHost{};
    toHost.sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER;
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    toHost.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toHost.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    toHost.buffer = destination;
    toHost.size = VK_WHOLE_SIZE;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 0,
                         nullptr, 1, &toHost, 0, nullptr);
}

}  // namespace varc::vulkan
