// SPDX-License-Identifier: Apache-2.0
#include "DeferredTargets.h"

#include <vector>

#include "varc/vulkan/DeviceImage.h"
#include "varc/vulkan/RenderPass.h"

namespace varc::render {

namespace {

constexpr VkPipelineStageFlags kAttachmentStages = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                                   VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                                   VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
constexpr VkAccessFlags kAttachmentAccess =
    VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;

// A pass with one colour attachment (|clearColor|: cleared from UNDEFINED, else loaded) and the
// G-buffer depth/stencil loaded in DEPTH_STENCIL_READ_ONLY_OPTIMAL: tested, never written, and
// sampled as _CameraDepthTexture at the same time.
Result<vulkan::UniqueHandle<VkRenderPass>> createReadOnlyDepthPass(VkDevice device, VkFormat color,
                                                                   VkFormat depth,
                                                                   bool clearColor) {
    std::array<VkAttachmentDescription, 2> attachments{};
    attachments[0].format = color;
    attachments[0].samples = VK_SAMPLE_COUNT_1_BIT;
    attachments[0].loadOp = clearColor ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
    attachments[0].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachments[0].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    attachments[0].stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[0].initialLayout =
        clearColor ? VK_IMAGE_LAYOUT_UNDEFINED : VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    attachments[0].finalLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
    attachments[1].format = depth;
    attachments[1].samples = VK_SAMPLE_COUNT_1_BIT;
    attachments[1].loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    attachments[1].storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachments[1].stencilLoadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
    attachments[1].stencilStoreOp = VK_ATTACHMENT_STORE_OP_STORE;
    attachments[1].initialLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;
    attachments[1].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;
    VkAttachmentReference colorRef{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkAttachmentReference depthRef{1, VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = 1;
    subpass.pColorAttachments = &colorRef;
    subpass.pDepthStencilAttachment = &depthRef;
    std::array<VkSubpassDependency, 2> dependencies{};
    dependencies[0] = {
        VK_SUBPASS_EXTERNAL,
        0,
        kAttachmentStages | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
        kAttachmentStages | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
        VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
            VK_ACCESS_TRANSFER_WRITE_BIT,
        kAttachmentAccess | VK_ACCESS_SHADER_READ_BIT,
        0};
    dependencies[1] = {
        0,
        VK_SUBPASS_EXTERNAL,
        kAttachmentStages,
        kAttachmentStages | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT,
        VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
        kAttachmentAccess | VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_TRANSFER_READ_BIT,
        0};
    return vulkan::createOneSubpassPass(device, attachments, subpass, dependencies);
}

void beginPass(VkCommandBuffer commands, VkRenderPass pass, VkFramebuffer framebuffer,
               VkRect2D area, const std::array<float, 4>* clear) {
    VkClearValue value{};
    if (clear) value.color = {{(*clear)[0], (*clear)[1], (*clear)[2], (*clear)[3]}};
    VkRenderPassBeginInfo info{};
    info.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
    info.renderPass = pass;
    info.framebuffer = framebuffer;
    info.renderArea = area;
    info.clearValueCount = clear ? 1u : 0u;
    info.pClearValues = clear ? &value : nullptr;
    vkCmdBeginRenderPass(commands, &info, VK_SUBPASS_CONTENTS_INLINE);
}

// Colour attachment <-> sampled image.
vulkan::LayoutTransition colorToSampled() {
    return {VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,      VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
            VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
            VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,         VK_ACCESS_SHADER_READ_BIT};
}
vulkan::LayoutTransition sampledToColor() {
    return {VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
            VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,
            VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
            0,
            VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
            VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT};
}

constexpr VkImageAspectFlags kDepthStencil =
    VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
constexpr VkPipelineStageFlags kDepthStages =
    VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;

}  // namespace

Result<DeferredTargets> DeferredTargets::create(vulkan::VulkanContext& context,
                                                const scene::Camera& camera) {
    DeferredTargets targets;
    const glm::vec4& b = camera.background;
    targets.mBackground = {b.r, b.g, b.b, b.a};
    vulkan::RenderTargetDesc desc;
    desc.width = camera.width;
    desc.height = camera.height;
    desc.color = vulkan::ColorFormat::Rgba8Srgb;
    // RT2 holds the normal in 32-bit floats instead of A2B10G10R10_UNORM (SHADER_ABI.md §6):
    // with any narrower format a one-step rounding difference of the normal at a glossy highlight
    // moves the pixel by ~10 LSB (measured with half floats: 11 LSB on a metallic sphere), so the
    // GPU could not be checked against the reference there.
    desc.extraColors = {
        vulkan::ColorFormat::Rgba8Srgb, vulkan::ColorFormat::Rgba32Float,
        camera.hdr ? vulkan::ColorFormat::Rgba16Float : vulkan::ColorFormat::Rgba8Unorm};
    // In HDR the light buffer is the frame: its background is the camera's. In LDR the decode
    // pass writes object pixels only, into an output cleared to the background.
    desc.extraClearColors = {{0, 0, 0, 0}, {0, 0, 0, 0}, targets.mBackground};
    desc.sampledDepth = true;
    desc.clearColor = {0, 0, 0, 0};
    desc.name = "deferred G-buffer";
    auto gbuffer = vulkan::RenderTarget::create(context, desc);
    if (!gbuffer) return gbuffer.error();
    targets.mGBuffer.emplace(std::move(*gbuffer));
    const vulkan::RenderTarget& g = *targets.mGBuffer;

    VkFormat lightFormat = vulkan::toVkFormat(g.attachmentFormat(kGBufferLight));
    auto lightPass =
        createReadOnlyDepthPass(context.device(), lightFormat, g.depthStencilFormat(), false);
    if (!lightPass) return lightPass.error();
    targets.mLightPass = std::move(*lightPass);
    auto lightFramebuffer = vulkan::createPassFramebuffer(
        context.device(), targets.mLightPass.get(),
        std::array{g.colorView(kGBufferLight), g.depthView()}, g.width(), g.height());
    if (!lightFramebuffer) return lightFramebuffer.error();
    targets.mLightFramebuffer = std::move(*lightFramebuffer);
    if (camera.hdr) return targets;

    vulkan::RenderTargetDesc outputDesc;
    outputDesc.width = camera.width;
    outputDesc.height = camera.height;
    outputDesc.color = vulkan::ColorFormat::Rgba8Unorm;
    outputDesc.depthStencil = false;
    outputDesc.clearColor = targets.mBackground;
    outputDesc.name = "deferred LDR output";
    auto output = vulkan::RenderTarget::create(context, outputDesc);
    if (!output) return output.error();
    targets.mOutput.emplace(std::move(*output));
    auto decodePass = createReadOnlyDepthPass(context.device(), VK_FORMAT_R8G8B8A8_UNORM,
                                              g.depthStencilFormat(), true);
    if (!decodePass) return decodePass.error();
    targets.mDecodePass = std::move(*decodePass);
    auto decodeFramebuffer = vulkan::createPassFramebuffer(
        context.device(), targets.mDecodePass.get(),
        std::array{targets.mOutput->colorView(), g.depthView()}, g.width(), g.height());
    if (!decodeFramebuffer) return decodeFramebuffer.error();
    targets.mDecodeFramebuffer = std::move(*decodeFramebuffer);
    return targets;
}

void DeferredTargets::beginLightPass(VkCommandBuffer commands) const {
    beginPass(commands, mLightPass.get(), mLightFramebuffer.get(), mGBuffer->area(), nullptr);
}

void DeferredTargets::beginDecodePass(VkCommandBuffer commands) const {
    beginPass(commands, mDecodePass.get(), mDecodeFramebuffer.get(), mGBuffer->area(),
              &mBackground);
}

void DeferredTargets::toLighting(VkCommandBuffer commands) const {
    for (uint32_t i : {kGBufferDiffuse, kGBufferSpecular, kGBufferNormal}) {
        vulkan::transitionLayout(commands, mGBuffer->colorImage(i), VK_IMAGE_ASPECT_COLOR_BIT,
                                 colorToSampled());
    }
    vulkan::transitionLayout(
        commands, mGBuffer->depthImage(), kDepthStencil,
        {VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
         VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL, kDepthStages,
         VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
         kDepthStages | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
         VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_SHADER_READ_BIT});
}

void DeferredTargets::fromLighting(VkCommandBuffer commands) const {
    for (uint32_t i : {kGBufferDiffuse, kGBufferSpecular, kGBufferNormal}) {
        vulkan::transitionLayout(commands, mGBuffer->colorImage(i), VK_IMAGE_ASPECT_COLOR_BIT,
                                 sampledToColor());
    }
    vulkan::transitionLayout(commands, mGBuffer->depthImage(), kDepthStencil,
                             {VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL,
                              VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                              kDepthStages | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT, 0, kDepthStages,
                              VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT |
                                  VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT});
}

void DeferredTargets::toDecode(VkCommandBuffer commands) const {
    vulkan::transitionLayout(commands, mGBuffer->colorImage(kGBufferLight),
                             VK_IMAGE_ASPECT_COLOR_BIT, colorToSampled());
}

void DeferredTargets::fromDecode(VkCommandBuffer commands) const {
    vulkan::transitionLayout(commands, mGBuffer->colorImage(kGBufferLight),
                             VK_IMAGE_ASPECT_COLOR_BIT, sampledToColor());
}

}  // namespace varc::render
