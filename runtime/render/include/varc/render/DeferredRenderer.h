// SPDX-License-Identifier: Apache-2.0
// Renders a deferred Scene (camera.path = deferred) with pack variants on Vulkan, as seed 002's
// deferred shading does: a G-buffer pass per object (LightMode Deferred: RT0–RT3, depth, stencil
// bits), then per light one draw of the deferred light shader's pass 0 with the variant the
// light's type, cookie and the camera's HDR select through the pack lookup, blended into the
// light buffer (HDR: One One; LDR: DstColor Zero on exp2(−c)), and in LDR the decode pass.
//
// Directional lights are drawn as a full-screen quad (_LightAsQuad = 1, rays in the NORMALs);
// point lights as a sphere and spot lights as a pyramid around their range (_LightAsQuad = 0),
// front faces with ZTest LEqual, or back faces with ZTest GEqual when the camera's near plane may
// cut the volume (LightVolume.h): only pixels the light can reach are shaded.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "varc/reader/Pack.h"
#include "varc/render/Renderer.h"
#include "varc/scene/Scene.h"
#include "varc/vulkan/VulkanContext.h"

namespace varc::render {

class DeferredRenderer final : public Renderer {
public:
    // |packs| must outlive the renderer. Objects' shaders need a "Deferred" pass; lights are drawn
    // with |lightShader| (pass 0 = light pass, pass 1 = LDR decode, as varc/DeferredLight).
    static Result<DeferredRenderer> create(vulkan::VulkanContext& context,
                                           std::vector<const reader::Pack*> packs,
                                           std::string lightShader = "varc/DeferredLight");

    // The frame: HDR = the light buffer (RgbaFloat), LDR = the decoded Rgba8 image whose alpha is
    // the clear alpha (the decode pass writes rgb only: its alpha, −log2(1) = 0, carries nothing).
    // Errors name the object or light: unknown shader, missing pass or variant, Vulkan failures.
    Result<RenderedFrame> render(const scene::Scene& scene) override;

    void usePipelineCache(VkPipelineCache cache) override;
    void useVariantRequests(reader::VariantRequests* requests,
                            variants::SelectionPolicy missPolicy) override;

    DeferredRenderer(DeferredRenderer&&) noexcept;
    DeferredRenderer& operator=(DeferredRenderer&&) noexcept;
    ~DeferredRenderer() override;

private:
    struct State;
    explicit DeferredRenderer(std::unique_ptr<State> state);
    std::unique_ptr<State> mState;
};

}  // namespace varc::render
