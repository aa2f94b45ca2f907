// SPDX-License-Identifier: Apache-2.0
// DeferredTargets: the images and render passes of one deferred frame size and mode: the G-buffer
// target (RT0–RT3 + a samplable depth/stencil), the light pass (RT3 + the depth/stencil read-only,
// so the depth is _CameraDepthTexture while the stencil masks the background) and, in LDR, the
// decode pass into the output image.
#pragma once

#include <array>
#include <optional>

#include "varc/scene/Scene.h"
#include "varc/vulkan/RenderTarget.h"

namespace varc::render {

// G-buffer attachment indices (SV_Target0..3).
inline constexpr uint32_t kGBufferDiffuse = 0;   // RT0 Rgba8Srgb: diffuse colour, occlusion
inline constexpr uint32_t kGBufferSpecular = 1;  // RT1 Rgba8Srgb: specular colour, smoothness
inline constexpr uint32_t kGBufferNormal = 2;    // RT2 Rgba32Float: normal · 0.5 + 0.5
// RT3: the light buffer (HDR Rgba16Float, LDR Rgba8Unorm).
inline constexpr uint32_t kGBufferLight = 3;

class DeferredTargets {
public:
    // Errors: those of RenderTarget::create and Vulkan.
    static Result<DeferredTargets> create(vulkan::VulkanContext& context,
                                          const scene::Camera& camera);

    const vulkan::RenderTarget& gbuffer() const { return *mGBuffer; }
    // LDR only: the decoded frame (Rgba8Unorm, cleared to the background).
    const vulkan::RenderTarget* output() const { return mOutput ? &*mOutput : nullptr; }
    VkRenderPass lightPass() const { return mLightPass.get(); }
    VkRenderPass decodePass() const { return mDecodePass.get(); }
    std::array<float, 4> background() const { return mBackground; }

    // Begins the light pass / the LDR decode pass (clears the output to the background).
    void beginLightPass(VkCommandBuffer commands) const;
    void beginDecodePass(VkCommandBuffer commands) const;

    // Layout changes around the passes (G-buffer steady layouts: colour and depth attachment
    // optimal). toLighting: RT0–RT2 become shader-readable, the depth read-only; fromLighting
    // restores them. toDecode/fromDecode do the same for RT3.
    void toLighting(VkCommandBuffer commands) const;
    void fromLighting(VkCommandBuffer commands) const;
    void toDecode(VkCommandBuffer commands) const;
    void fromDecode(VkCommandBuffer commands) const;

private:
    std::optional<vulkan::RenderTarget> mGBuffer;
    std::optional<vulkan::RenderTarget> mOutput;
    vulkan::UniqueHandle<VkRenderPass> mLightPass, mDecodePass;
    vulkan::UniqueHandle<VkFramebuffer> mLightFramebuffer, mDecodeFramebuffer;
    std::array<float, 4> mBackground{};
};

}  // namespace varc::render
