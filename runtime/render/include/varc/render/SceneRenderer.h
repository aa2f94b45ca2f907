// SPDX-License-Identifier: Apache-2.0
// Renders any scene: the forward, single-pass or deferred renderer, as the scene's camera path
// asks, sharing one Vulkan context, one set of packs and one pipeline cache.
#pragma once

#include <memory>
#include <vector>

#include "varc/reader/Pack.h"
#include "varc/render/DeferredRenderer.h"
#include "varc/render/ForwardRenderer.h"
#include "varc/render/Renderer.h"
#include "varc/render/SinglePassRenderer.h"
#include "varc/vulkan/VulkanContext.h"

namespace varc::render {

class SceneRenderer final : public Renderer {
public:
    // |packs| must outlive the renderer; shaders are found by name in the first pack that has
    // them. Deferred scenes draw their lights with "varc/DeferredLight".
    static Result<SceneRenderer> create(vulkan::VulkanContext& context,
                                        std::vector<const reader::Pack*> packs);

    // By scene.camera.path: "forward" (default), "single_pass" or "deferred".
    Result<RenderedFrame> render(const scene::Scene& scene) override;

    void usePipelineCache(VkPipelineCache cache) override;
    void useVariantRequests(reader::VariantRequests* requests,
                            variants::SelectionPolicy missPolicy) override;

private:
    SceneRenderer(ForwardRenderer forward, SinglePassRenderer singlePass,
                  DeferredRenderer deferred);
    Renderer& rendererFor(scene::RenderPath path);

    ForwardRenderer mForward;
    SinglePassRenderer mSinglePass;
    DeferredRenderer mDeferred;
};

}  // namespace varc::render
